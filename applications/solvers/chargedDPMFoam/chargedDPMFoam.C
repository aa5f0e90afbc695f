/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    chargedDPMFoam

Group
    grpLagrangianSolvers

Description
    Gas-coupled solver for charged ellipsoidal particles: OpenFOAM's DPMFoam
    (v1912) with the charged cloud. The incompressible continuous phase is
    solved by PIMPLE with its volume fraction alphac = 1 - theta from the
    cloud and the two-way momentum exchange of the cloud's coupled forces
    (drag, pressure gradient, ...: cloudSU, cloudVolSUSu), as DPMFoam does:
    its pEqn.H is included as it is; UcEqn.H (this folder) is DPMFoam's
    momentum equation, or its conservative form with the cloud's
    solution/momentumCoupling conservativeImplicit. Then cloudSU is
    implicit in the drag and the parcels get their share of the carrier's
    velocity change after the PIMPLE loop (correctCoupling): the momentum
    one phase gains is the other's loss.

    The cloud (constant/<cloud>Properties, -cloud option, default 'cloud')
    is the basicChargedCloud of chargedParticleFoam: electrostatics,
    contact, tribocharging, injection and OpenFOAM's particle forces, with
    ellipsoidDrag for orientation-dependent drag. Electrostatic and contact
    forces act on the particles only; the gas feels the coupled forces.

    Case set-up as DPMFoam's: constant/transportProperties (continuousPhase,
    rho.<phase>, transportModel, nu), turbulenceProperties.<phase>, fields
    U.<phase> and p, constantProperties/alphaMax in the cloud properties.

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "singlePhaseTransportModel.H"
#include "PhaseIncompressibleTurbulenceModel.H"
#include "pimpleControl.H"
#include "basicChargedCloud.H"
#include "runProgress.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Transient solver for an incompressible gas coupled to a cloud of"
        " charged ellipsoidal particles (DPMFoam with the charged cloud)."
    );
    argList::addOption
    (
        "cloud",
        "name",
        "specify alternative cloud name; default is 'cloud'"
    );

    #include "postProcess.H"

    #include "addCheckCaseOptions.H"
    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "createControl.H"
    #include "createTimeControls.H"
    #include "createFields.H"
    #include "initContinuityErrs.H"

    runProgress progress(runTime);

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        #include "readTimeControls.H"
        #include "CourantNo.H"
        #include "setDeltaT.H"

        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        continuousPhaseTransport.correct();
        muc = rhoc*continuousPhaseTransport.nu();

        Info<< "Evolving " << parcels.name() << endl;
        parcels.evolve();

        // Continuous phase volume fraction from the particles
        alphac = max(1.0 - parcels.theta(), alphacMin);
        alphac.correctBoundaryConditions();
        alphacf = fvc::interpolate(alphac);
        alphaPhic = alphacf*phic;

        // Momentum from the particles: the implicit part in the Uc matrix,
        // the explicit part as a force field in the pressure equation
        // (DPMFoam v1912)
        fvVectorMatrix cloudSU(parcels.SU(Uc));
        volVectorField cloudVolSUSu
        (
            IOobject
            (
                "cloudVolSUSu",
                runTime.timeName(),
                mesh
            ),
            mesh,
            dimensionedVector(cloudSU.dimensions()/dimVolume, Zero),
            zeroGradientFvPatchVectorField::typeName
        );

        cloudVolSUSu.primitiveFieldRef() = -cloudSU.source()/mesh.V();
        cloudVolSUSu.correctBoundaryConditions();
        cloudSU.source() = Zero;

        // --- Pressure-velocity PIMPLE corrector loop
        while (pimple.loop())
        {
            #include "UcEqn.H"

            // --- PISO loop
            while (pimple.correct())
            {
                #include "pEqn.H"
            }

            if (pimple.turbCorr())
            {
                continuousPhaseTurbulence->correct();
            }
        }

        // The parcels' share of the implicit drag (momentumCoupling
        // conservativeImplicit; nothing with OpenFOAM's source terms)
        parcels.correctCoupling(Uc);

        runTime.write();

        runTime.printExecutionTime(Info);
        progress.report();
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
