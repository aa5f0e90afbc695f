/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidParcel.H"

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
        td.part() = trackingData::tpVelocityHalfStep;
        ParcelType::move(cloud, td, trackTime);
        td.part() = trackingData::tpLinearTrack;
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
    // of the orientation with the kicked angular momentum and the contact
    // body for the collision model, once, where the move ends: in parallel
    // Cloud::move calls move again for every parcel, finished or not,
    // until no parcel changes processor, and a parcel may arrive with its
    // step done
    const bool ends = this->stepFraction() < 1 || received_;
    const bool keep = ParcelType::move(cloud, td, trackTime);
    if (ends && keep && !td.switchProcessor)
    {
        rotate(trackTime);
        received_ = false;
        cloud.parcelMoved
        (
            static_cast<typename TrackCloudType::parcelType&>(*this)
        );
    }
    return keep;
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
