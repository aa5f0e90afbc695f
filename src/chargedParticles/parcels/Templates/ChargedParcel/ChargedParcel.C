/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedParcel.H"
#include "inputLimits.H"
#include "OStringStream.H"
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
    material_(p.material_),
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
    material_(p.material_),
    chargingRecords_(p.chargingRecords_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
void Foam::ChargedParcel<ParcelType>::stopNotFinite
(
    const TrackCloudType& cloud,
    const bool afterMove
) const
{
    using inputLimits::finite;

    // The first term that is not finite, with where it comes from (a few
    // comparisons per parcel and kick)
    auto value = [](const vector& v)
    {
        OStringStream os;
        os << v;
        return os.str();
    };
    string term;
    if (afterMove)
    {
        if (!finite(this->U()))
        {
            term = "the velocity U = " + value(this->U()) + " after the"
                " drift: from the carrier's forces (particleForces, e.g."
                " drag and gravity)";
        }
        else if (!finite(this->angularMomentum()))
        {
            term = "the angular momentum " + value(this->angularMomentum())
              + " after the drift: from the carrier's forces"
                " (particleForces)";
        }
    }
    else
    {
        if (!finite(fE_))
        {
            term = "the electrostatic force fE = " + value(fE_) + ": from"
                " electrostaticsModel " + cloud.electrostatics().type();
        }
        else if (!finite(tE_))
        {
            term = "the electrostatic torque tE = " + value(tE_) + ": from"
                " electrostaticsModel " + cloud.electrostatics().type();
        }
        else if (!finite(this->f()))
        {
            term = "the contact force f = " + value(this->f()) + ": from"
                " collisionModel " + cloud.collision().type();
        }
        else if (!finite(this->torque()))
        {
            term = "the contact torque " + value(this->torque()) + ": from"
                " collisionModel " + cloud.collision().type();
        }
        else if (!std::isfinite(q_))
        {
            term = "the charge q = " + Foam::name(q_) + ": from the contact"
                " charging (triboChargingModel "
              + cloud.triboCharging().type() + ")";
        }
        else if (!finite(this->U()) || !finite(this->angularMomentum()))
        {
            term = "the velocity U = " + value(this->U()) + " or the angular"
                " momentum " + value(this->angularMomentum())
              + " before the kick";
        }
    }
    if (term.empty())
    {
        return;
    }

    FatalErrorInFunction
        << "Parcel (origProc " << this->origProc() << ", origId "
        << this->origId() << ") at " << this->position() << ", t = "
        << cloud.db().time().value() << " s (time index "
        << cloud.db().time().timeIndex() << "): " << term.c_str()
        << ", is not finite. The run stops before it reaches the parcels'"
        << " files. Check the model named and its entries, and the time step"
        << exit(FatalError);
}


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
        checkFinite(cloud, false);
        electrostaticKick(cloud, trackTime);
    }

    const bool keep = ParcelType::move(cloud, td, trackTime);
    checkFinite(cloud, true);

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
