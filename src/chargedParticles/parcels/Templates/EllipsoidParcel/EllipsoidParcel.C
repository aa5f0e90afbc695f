/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidParcel.H"
#include "transform.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::EllipsoidParcel<ParcelType>::EllipsoidParcel
(
    const EllipsoidParcel<ParcelType>& p
)
:
    ParcelType(p),
    semiAxes_(p.semiAxes_),
    orientation_(p.orientation_)
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
    orientation_(p.orientation_)
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
    if (td.part() == trackingData::tpRotationalTrack)
    {
        // Drift of the orientation with the kicked angular momentum
        td.keepParticle = true;
        td.switchProcessor = false;

        if (this->angularMomentum() != vector::zero)
        {
            rigidBodyRotation::freeRotation
            (
                orientation_,
                this->angularMomentum(),
                principalMoments(),
                trackTime
            );
        }
        return td.keepParticle;
    }

    return ParcelType::move(cloud, td, trackTime);
}


template<class ParcelType>
void Foam::EllipsoidParcel<ParcelType>::transformProperties(const tensor& T)
{
    ParcelType::transformProperties(T);

    // Rotate the body with the transformation (rotational cyclics)
    orientation_ = (quaternion(T)*orientation_).normalized();
}


template<class ParcelType>
void Foam::EllipsoidParcel<ParcelType>::transformProperties
(
    const vector& separation
)
{
    ParcelType::transformProperties(separation);
}


// * * * * * * * * * * * * * * IOStream operators  * * * * * * * * * * * * * //

#include "EllipsoidParcelIO.C"

// ************************************************************************* //
