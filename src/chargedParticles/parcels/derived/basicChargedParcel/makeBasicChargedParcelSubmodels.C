/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Description
    Run-time selection tables of basicChargedCloud: OpenFOAM's kinematic
    submodels plus the chargedFoam ones.

\*---------------------------------------------------------------------------*/

#include "basicChargedCloud.H"

// OpenFOAM's kinematic submodels
#include "makeParcelCloudFunctionObjects.H"
#include "makeParcelForces.H"
#include "makeParcelDispersionModels.H"
#include "makeParcelInjectionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeParcelSurfaceFilmModels.H"

// chargedFoam submodels
#include "ExplicitParcelInjection.H"
#include "ParticleHistory.H"
#include "NoElectrostatics.H"
#include "DirectCoulomb.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(basicChargedCloud);
makeCloudFunctionObjectType(ParticleHistory, basicChargedCloud);

// Kinematic
makeParcelForces(basicChargedCloud);
makeParcelDispersionModels(basicChargedCloud);
makeParcelInjectionModels(basicChargedCloud);
makeInjectionModelType(ExplicitParcelInjection, basicChargedCloud);
makeParcelPatchInteractionModels(basicChargedCloud);
makeParcelStochasticCollisionModels(basicChargedCloud);
makeParcelSurfaceFilmModels(basicChargedCloud);

// Charged
makeElectrostaticsModel(basicChargedCloud);
makeElectrostaticsModelType(NoElectrostatics, basicChargedCloud);
makeElectrostaticsModelType(DirectCoulomb, basicChargedCloud);


// ************************************************************************* //
