/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    chargedParticleFoam

Group
    grpLagrangianSolvers

Description
    Particles-only solver for charged particles in vacuum or a quiescent dry
    gas: no gas flow is built or solved. The cloud (constant/<cloud>Properties)
    carries the physics: electrostatics, contact, injection, gravity.

    The cloud's carrier is a uniform, constant medium read from the optional
    constant/carrierProperties (rho [kg/m3], mu [Pa s], U [m/s]; default
    vacuum: 0, 0, (0 0 0)); it only matters to particle force models that
    use it (e.g. drag).

\*---------------------------------------------------------------------------*/

#include "fvCFD.H"
#include "basicChargedCloud.H"
#include "checkedEntry.H"
#include "runProgress.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Particles-only solver for charged particles (no gas is solved)."
    );
    argList::addOption
    (
        "cloud",
        "name",
        "specify alternative cloud name; default is 'cloud'"
    );

    #include "setRootCaseLists.H"
    #include "createTime.H"
    #include "createMesh.H"
    #include "readGravitationalAcceleration.H"
    #include "createFields.H"

    runProgress progress(runTime);

    Info<< "\nStarting time loop\n" << endl;

    while (runTime.run())
    {
        ++runTime;

        Info<< "Time = " << runTime.timeName() << nl << endl;

        parcels.evolve();

        runTime.write();

        runTime.printExecutionTime(Info);
        progress.report();
    }

    Info<< "End\n" << endl;

    return 0;
}


// ************************************************************************* //
