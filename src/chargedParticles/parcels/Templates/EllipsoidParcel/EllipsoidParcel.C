/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidParcel.H"
#include "meshTools.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::EllipsoidParcel<ParcelType>::EllipsoidParcel
(
    const EllipsoidParcel<ParcelType>& p
)
:
    ParcelType(p),
    semiAxes_(p.semiAxes_),
    orientation_(p.orientation_),
    received_(p.received_)
{}


template<class ParcelType>
Foam::EllipsoidParcel<ParcelType>::EllipsoidParcel
(
    const EllipsoidParcel<ParcelType>& p,
    const polyMesh& mesh
)
:
    ParcelType(p, mesh),
    semiAxes_(p.semiAxes_),
    orientation_(p.orientation_),
    received_(p.received_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
bool Foam::EllipsoidParcel<ParcelType>::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    if (td.part() != trackingData::tpLinearTrack)
    {
        return ParcelType::move(cloud, td, trackTime);
    }

    // The first half kick of the leapfrog, in the same pass over the cloud
    // as the drift when the cloud asks for it (EllipsoidCloud::moveCollide):
    // the CollidingParcel's kick with the contact force and torque
    if (kicksInMove(cloud, td))
    {
        contactKick(trackTime);
    }

    // A parcel kicked to the speed of light has met forces beyond any
    // physical range: tracking it would cross the mesh without end
    if (!inputLimits::magBelow(this->U(), inputLimits::speedOfLight))
    {
        FatalIOErrorInFunction(cloud.particleProperties())
            << "Parcel (origProc " << this->origProc() << ", origId "
            << this->origId() << ") at " << this->position() << " has the"
            << " velocity U = " << this->U() << " m/s at t = "
            << cloud.db().time().value() << " s, not below the speed of"
            << " light: the forces on it are beyond any physical range."
            << " Check the parcels' charges q and sizes, youngsModulus and"
            << " the time step deltaT" << exit(FatalIOError);
    }

    // The drift (lazy or tracked: LazyTrackingParcel), then the rotation
    // of the orientation with the kicked angular momentum (a sphere's
    // where the cloud integrates them: EllipsoidCloud::sphereOrientation)
    // and the contact body for the collision model, once, where the move
    // ends: in parallel Cloud::move calls move again for every parcel,
    // finished or not, until no parcel changes processor, and a parcel
    // may arrive with its step done
    const bool ends = this->stepFraction() < 1 || received_;
    const bool keep = ParcelType::move(cloud, td, trackTime);
    if (ends && keep && !td.switchProcessor)
    {
        if (!isSphere() || cloud.sphereOrientation())
        {
            rotate(trackTime);
        }
        received_ = false;
        cloud.parcelMoved
        (
            static_cast<typename TrackCloudType::parcelType&>(*this)
        );
    }
    return keep;
}


template<class ParcelType>
template<class TrackCloudType>
void Foam::EllipsoidParcel<ParcelType>::setCellValues
(
    TrackCloudType& cloud,
    trackingData& td
)
{
    if (!cloud.gravityOnly())
    {
        ParcelType::setCellValues(cloud, td);
        return;
    }

    // KinematicParcel::setCellValues' density, limited as there; no force
    // reads the carrier's velocity or viscosity
    td.rhoc() =
        td.rhoInterp().interpolate
        (
            this->coordinates(),
            this->currentTetIndices()
        );
    if (td.rhoc() < cloud.constProps().rhoMin())
    {
        td.rhoc() = cloud.constProps().rhoMin();
    }
}


template<class ParcelType>
template<class TrackCloudType>
void Foam::EllipsoidParcel<ParcelType>::calcDispersion
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar dt
)
{
    if (!cloud.gravityOnly())
    {
        ParcelType::calcDispersion(cloud, td, dt);
    }
}


template<class ParcelType>
template<class TrackCloudType>
void Foam::EllipsoidParcel<ParcelType>::calc
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar dt
)
{
    if (!cloud.gravityOnly())
    {
        ParcelType::calc(cloud, td, dt);
        return;
    }

    // KinematicParcel::calc and calcVelocity (OpenFOAM v1912) with only
    // gravity forces, uncoupled: Fcp = 0, so acp = (0 Uc + 0)/m = +0 and
    // bcp = 0; massEff = m (gravity adds no mass); Fncp.Su is the sum of
    // GravityForce::calcNonCoupled's m g (1 - rhoc/rho) from Zero. The
    // same operations in the same order (the zero sums included: they turn
    // -0 into +0), so the velocity is bit-identical to the force list's
    const scalar m = this->mass();
    vector FncpSu = Zero;
    for (const vector& g : cloud.gravity())
    {
        FncpSu += m*g*(1.0 - td.rhoc()/this->rho());
    }
    const vector acp = Zero;
    const vector ancp = (FncpSu + vector(Zero))/m;
    vector Unew =
        this->U() + cloud.UIntegrator().delta(this->U(), dt, acp + ancp, 0);

    const polyMesh& mesh = cloud.pMesh();
    meshTools::constrainDirection(mesh, mesh.solutionD(), Unew);
    this->U() = Unew;
}


template<class ParcelType>
void Foam::EllipsoidParcel<ParcelType>::rotate(const scalar dt)
{
    if (isSphere())
    {
        rigidBodyRotation::sphereRotation
        (
            orientation_,
            this->angularMomentum(),
            rigidBodyRotation::sphereMoment(this->mass(), semiAxes_.x()),
            dt
        );
    }
    else if (this->angularMomentum() != vector::zero)
    {
        rigidBodyRotation::freeRotation
        (
            orientation_,
            this->angularMomentum(),
            principalMoments(),
            dt
        );
    }
}


template<class ParcelType>
void Foam::EllipsoidParcel<ParcelType>::transformProperties(const tensor& T)
{
    ParcelType::transformProperties(T);

    // Rotate the body with the transformation (rotational cyclics)
    orientation_ = (quaternion(T)*orientation_).normalized();
}


// * * * * * * * * * * * * * * IOStream operators  * * * * * * * * * * * * * //

#include "EllipsoidParcelIO.C"

// ************************************************************************* //
