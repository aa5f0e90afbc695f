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
#include "makeParcelCollisionModels.H"
#include "makeParcelPatchInteractionModels.H"
#include "makeParcelStochasticCollisionModels.H"
#include "makeParcelSurfaceFilmModels.H"

// chargedFoam submodels
#include "ExplicitParcelInjection.H"
#include "ParticleHistory.H"
#include "NoElectrostatics.H"
#include "DirectCoulomb.H"
#include "PeriodicCoulomb.H"
#include "CutoffCoulomb.H"
#include "MeshPoisson.H"
#include "ImageCoulomb.H"
#include "AutoElectrostatics.H"
#include "NoNearField.H"
#include "InducedDipoleNearField.H"
#include "BemNearField.H"
#include "EllipsoidCollision.H"
#include "OscillatingFrameForce.H"
#include "EllipsoidDragForce.H"
#include "NoTriboCharging.H"
#include "RaseraTriboCharging.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

makeParcelCloudFunctionObjects(basicChargedCloud);
makeCloudFunctionObjectType(ParticleHistory, basicChargedCloud);

// Kinematic and colliding (OpenFOAM's sphere DEM: pairCollision)
makeParcelForces(basicChargedCloud);
makeParticleForceModelType(OscillatingFrameForce, basicChargedCloud);
makeParticleForceModelType(EllipsoidDragForce, basicChargedCloud);
makeParcelDispersionModels(basicChargedCloud);
makeParcelInjectionModels(basicChargedCloud);
makeInjectionModelType(ExplicitParcelInjection, basicChargedCloud);
makeParcelPatchInteractionModels(basicChargedCloud);
makeParcelCollisionModels(basicChargedCollidingCloud);
makeCollisionModelType(EllipsoidCollision, basicChargedCollidingCloud);
makeParcelStochasticCollisionModels(basicChargedCloud);
makeParcelSurfaceFilmModels(basicChargedCloud);

// Charged
makeElectrostaticsModel(basicChargedCloud);
makeElectrostaticsModelType(NoElectrostatics, basicChargedCloud);
makeElectrostaticsModelType(DirectCoulomb, basicChargedCloud);
makeElectrostaticsModelType(PeriodicCoulomb, basicChargedCloud);
makeElectrostaticsModelType(CutoffCoulomb, basicChargedCloud);
makeElectrostaticsModelType(MeshPoisson, basicChargedCloud);
makeElectrostaticsModelType(ImageCoulomb, basicChargedCloud);
makeElectrostaticsModelType(AutoElectrostatics, basicChargedCloud);

makeNearFieldModel(basicChargedCloud);
makeNearFieldModelType(NoNearField, basicChargedCloud);
makeNearFieldModelType(InducedDipoleNearField, basicChargedCloud);
makeNearFieldModelType(BemNearField, basicChargedCloud);

makeTriboChargingModel(basicChargedCloud);
makeTriboChargingModelType(NoTriboCharging, basicChargedCloud);
makeTriboChargingModelType(RaseraTriboCharging, basicChargedCloud);
makeTriboChargingModelType(WorkFunctionTriboCharging, basicChargedCloud);


// ************************************************************************* //
