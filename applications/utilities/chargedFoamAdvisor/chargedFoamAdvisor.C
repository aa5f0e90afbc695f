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

    With -rungs it also measures every applicable far-field rung on the
    parcels (ElectrostaticsSurvey): the force error against the scene's
    reference, the cost per evaluation and the memory, and recommends the
    cheapest rung within -accuracy. The table goes to the log and to
    postProcessing/advisor/<time>/rungs.dat, and etc/python/plotRungs.py
    draws it to rungs.png beside it (error against cost) when python3 with
    matplotlib is there.

    The carrier: a gas case (constant/transportProperties with
    continuousPhase, as chargedDPMFoam reads it) or the uniform medium of
    constant/carrierProperties (chargedParticleFoam; default vacuum).

Usage
    chargedFoamAdvisor [-cloud name] [-time t | -latestTime] [-parallel]
        [-rungs [-accuracy 0.05] [-sampleSize 1000] [-repeats 3]]

    The last lines: "N warning(s)" (for scripts; OpenFOAM's run-time
    control ends every application with exit status 0) and "End".

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "basicChargedCloud.H"
#include "checkedEntry.H"
#include "timeSelector.H"
#include "ElectrostaticsSurvey.H"
#include "OFstream.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

//- The command line
void addOptions()
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
    argList::addBoolOption
    (
        "rungs",
        "measure every applicable far-field rung on the parcels and"
        " recommend the cheapest within -accuracy"
    );
    argList::addOption
    (
        "accuracy",
        "value",
        "rms force error the recommended rung must meet; default 0.05"
    );
    argList::addOption
    (
        "sampleSize",
        "n",
        "parcels compared (a random sample above); default 1000"
    );
    argList::addOption
    (
        "repeats",
        "n",
        "timed evaluations per rung (median); default 3"
    );
}


//- The survey's table to postProcessing/advisor/<time>/rungs.dat and its
//  plot (the master)
template<class Survey>
void writeRungs(const Survey& survey, const Time& runTime)
{
    if (Pstream::master())
    {
        const fileName dir
        (
            runTime.globalPath()/"postProcessing"/"advisor"
           /runTime.timeName()
        );
        mkDir(dir);
        {
            OFstream os(dir/"rungs.dat");
            survey.writeTable(os);
        }
        Info<< "Table written to " << dir/"rungs.dat" << endl;
        const fileName plot
        (
            getEnv("CHARGEDFOAM_DIR")/"etc"/"python"/"plotRungs.py"
        );
        // Debian's python3 has matplotlib (etc/setup installs it)
        const fileName py
        (
            isFile("/usr/bin/python3") ? "/usr/bin/python3" : "python3"
        );
        if (isFile(plot))
        {
            Foam::system
            (
                py + " " + plot + " " + dir/"rungs.dat" + " "
              + dir/"rungs.png"
            );
        }
    }
}


int main(int argc, char *argv[])
{
    addOptions();

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

    dictionary surveyDict("advisor");
    if (args.found("accuracy"))
    {
        surveyDict.add("accuracy", args.get<scalar>("accuracy"));
    }
    for (const word opt : {"sampleSize", "repeats"})
    {
        if (args.found(opt))
        {
            surveyDict.add(opt, args.get<label>(opt));
        }
    }

    // The carrier: the uniform medium of chargedParticleFoam, or the gas
    // density and viscosity of a chargedDPMFoam case (the breakdown check
    // and the drag response time use them)
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
            const scalar rho =
                transport.get<dimensionedScalar>("rho." + phase).value();
            rhoc == dimensionedScalar("rho", dimDensity, rho);
            // Newtonian carrier (DPMFoam's singlePhaseTransportModel)
            scalar nu = 0;
            if (transport.readIfPresent("nu", nu))
            {
                muc == dimensionedScalar("mu", dimDynamicViscosity, rho*nu);
            }
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

        if (args.found("rungs"))
        {
            ElectrostaticsSurvey<basicChargedCloud::chargedCloudType> survey
            (
                parcels,
                surveyDict
            );
            survey.run(parcels.subModelProperties());
            survey.write(Info);

            writeRungs(survey, runTime);
            Info<< endl;
        }
    }

    reduce(nWarnings, maxOp<label>());
    Info<< nWarnings << " warning(s)" << nl << "End\n" << endl;
    return 0;
}


// ************************************************************************* //
