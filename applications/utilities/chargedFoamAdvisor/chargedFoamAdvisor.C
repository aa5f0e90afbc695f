/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    chargedFoamAdvisor

Description
    The scene check of a case at any written time, without running it: the
    parcels, charges, surface fields, polarisable parcels and their gaps,
    walls and wall distances, the models and the time step against the
    Coulomb-collision step, and a warning naming the entry to change where
    the chosen model is clearly inadequate or has nothing to compute (the
    same check the solvers log at their first step: SceneCheck). Serial or
    parallel (-parallel on a decomposed case).

    The carrier: a gas case (constant/transportProperties with
    continuousPhase, as chargedDPMFoam reads it) or the uniform medium of
    constant/carrierProperties (chargedParticleFoam; default vacuum).

Usage
    chargedFoamAdvisor [-cloud name] [-time t | -latestTime] [-parallel]

    The last lines: "N warning(s)" (for scripts; OpenFOAM's run-time
    control ends every application with exit status 0) and "End".

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "basicChargedCloud.H"
#include "timeSelector.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "The scene check of a case at a written time: the scene in the terms"
        " that decide the electrostatics model, with warnings"
    );
    timeSelector::addOptions(true, false);
    argList::addOption
    (
        "cloud",
        "name",
        "specify alternative cloud name; default is 'cloud'"
    );

    #include "setRootCase.H"
    #include "createTime.H"
    instantList times = timeSelector::select0(runTime, args);
    if (times.empty())
    {
        times.append(runTime.findClosestTime(runTime.startTime().value()));
    }
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"

    const word cloudName(args.lookupOrDefault<word>("cloud", "cloud"));

    // The carrier: the uniform medium of chargedParticleFoam, or the gas
    // density of a chargedDPMFoam case (only the breakdown check uses it)
    #include "createCarrierMedium.H"
    {
        IOdictionary transport
        (
            IOobject
            (
                "transportProperties", runTime.constant(), mesh,
                IOobject::READ_IF_PRESENT, IOobject::NO_WRITE, false
            )
        );
        word phase;
        if (transport.readIfPresent("continuousPhase", phase))
        {
            rhoc == dimensionedScalar
            (
                "rho",
                dimDensity,
                transport.get<dimensionedScalar>("rho." + phase).value()
            );
        }
    }

    label nWarnings = 0;
    forAll(times, timei)
    {
        runTime.setTime(times[timei], timei);
        Info<< "Time = " << runTime.timeName() << endl;
        mesh.readUpdate();

        basicChargedCloud parcels(cloudName, rhoc, Uc, muc, g);
        if (returnReduce(parcels.size(), sumOp<label>()) == 0)
        {
            Info<< "No parcels of cloud " << cloudName << " at time "
                << runTime.timeName() << " (they are injected later: run"
                << " a step, or choose a written time with parcels)" << nl
                << endl;
            continue;
        }
        nWarnings += parcels.checkScene().size();
    }

    reduce(nWarnings, maxOp<label>());
    Info<< nWarnings << " warning(s)" << nl << "End\n" << endl;
    return 0;
}


// ************************************************************************* //
