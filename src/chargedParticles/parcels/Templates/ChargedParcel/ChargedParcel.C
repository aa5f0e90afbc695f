/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedParcel.H"
#include "transform.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::ChargedParcel<ParcelType>::ChargedParcel(const ChargedParcel<ParcelType>& p)
:
    ParcelType(p),
    q_(p.q_),
    epsilonR_(p.epsilonR_),
    fE_(p.fE_),
    tE_(p.tE_),
    E_(p.E_),
    dipole_(p.dipole_),
    chargingRecords_(p.chargingRecords_)
{}


template<class ParcelType>
Foam::ChargedParcel<ParcelType>::ChargedParcel
(
    const ChargedParcel<ParcelType>& p,
    const polyMesh& mesh
)
:
    ParcelType(p, mesh),
    q_(p.q_),
    epsilonR_(p.epsilonR_),
    fE_(p.fE_),
    tE_(p.tE_),
    E_(p.E_),
    dipole_(p.dipole_),
    chargingRecords_(p.chargingRecords_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
bool Foam::ChargedParcel<ParcelType>::move
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    if
    (
        td.part() == trackingData::tpVelocityHalfStep
     || this->kicksInMove(cloud, td)
    )
    {
        // Leapfrog half kick with the electrostatic force and torque at
        // the current position (the first one of a step may come with the
        // move, see EllipsoidParcel::move); the base layer adds the
        // contact force and torque
        this->U() += (0.5*trackTime/this->mass())*fE_;
        this->angularMomentum() += (0.5*trackTime)*tE_;
    }

    const bool keep = ParcelType::move(cloud, td, trackTime);

    // A parcel removed on a boundary face (escaped through an open patch)
    // takes its charge out of the domain: book it for the charge balance
    if (!td.keepParticle && this->onBoundaryFace())
    {
        cloud.addEscapedCharge(this->patch(), q_);
    }

    return keep;
}


template<class ParcelType>
void Foam::ChargedParcel<ParcelType>::transformProperties(const tensor& T)
{
    ParcelType::transformProperties(T);
    fE_ = transform(T, fE_);
    tE_ = transform(T, tE_);
    E_ = transform(T, E_);
    dipole_ = transform(T, dipole_);
}


template<class ParcelType>
void Foam::ChargedParcel<ParcelType>::transformProperties
(
    const vector& separation
)
{
    ParcelType::transformProperties(separation);
}


// * * * * * * * * * * * * * * IOStream operators  * * * * * * * * * * * * * //

#include "ChargedParcelIO.C"

// ************************************************************************* //
