/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "LazyTrackingParcel.H"
#include "transform.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::LazyTrackingParcel<ParcelType>::LazyTrackingParcel
(
    const LazyTrackingParcel<ParcelType>& p
)
:
    ParcelType(p),
    drift_(p.drift_),
    allowedDrift_(p.allowedDrift_),
    centre_(p.centre_),
    centreValid_(p.centreValid_)
{}


template<class ParcelType>
Foam::LazyTrackingParcel<ParcelType>::LazyTrackingParcel
(
    const LazyTrackingParcel<ParcelType>& p,
    const polyMesh& mesh
)
:
    ParcelType(p, mesh),
    drift_(p.drift_),
    allowedDrift_(p.allowedDrift_),
    centre_(p.centre_),
    centreValid_(p.centreValid_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

template<class ParcelType>
template<class TrackCloudType>
bool Foam::LazyTrackingParcel<ParcelType>::move
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

    if (cloud.trackingTolerance() > 0 && this->active())
    {
        if (driftInCell(cloud, td, trackTime))
        {
            return td.keepParticle;
        }
        // The rest of the step is tracked, starting with the drift
        trackDrift();
    }

    const bool keep = ParcelType::move(cloud, td, trackTime);
    centreValid_ = false;
    allowedDrift_ = -1;
    return keep;
}


template<class ParcelType>
template<class TrackCloudType>
bool Foam::LazyTrackingParcel<ParcelType>::driftInCell
(
    TrackCloudType& cloud,
    trackingData& td,
    const scalar trackTime
)
{
    typename TrackCloudType::parcelType& p =
        static_cast<typename TrackCloudType::parcelType&>(*this);
    typename TrackCloudType::parcelType::trackingData& ttd =
        static_cast<typename TrackCloudType::parcelType::trackingData&>(td);

    ttd.switchProcessor = false;
    ttd.keepParticle = true;

    const polyMesh& mesh = this->mesh();
    const label celli = this->cell();
    const scalar l = cloud.cellLengthScale()[celli];

    if (allowedDrift_ < 0)
    {
        // Half the distance of the tracked position to the nearest face
        // plane of the cell (half: faces need not be flat), and at most
        // the tolerance
        const point x = this->position();
        scalar dMin = GREAT;
        for (const label facei : mesh.cells()[celli])
        {
            const vector& Sf = mesh.faceAreas()[facei];
            dMin = min
            (
                dMin,
                mag((x - mesh.faceCentres()[facei]) & Sf)/mag(Sf)
            );
        }
        allowedDrift_ = min(0.5*dMin, cloud.trackingTolerance()*l);
        centre_ = x + drift_;
        centreValid_ = true;
    }

    // KinematicParcel::move, segment by segment (maxCo), with the
    // displacement added to the drift instead of tracked
    const cloudSolution& solution = cloud.solution();
    const scalar maxCo = solution.maxCo();
    while (ttd.keepParticle && p.stepFraction() < 1)
    {
        const vector s = trackTime*this->U();
        scalar f = 1 - p.stepFraction();
        f = min(f, maxCo);
        f = min(f, maxCo*l/max(SMALL*l, mag(s)));

        if (magSqr(drift_ + f*s) >= sqr(allowedDrift_))
        {
            return false;
        }

        const point start = centre();
        drift_ += f*s;
        centre_ += f*s;
        p.stepFraction() += f;

        const scalar dt = f*trackTime;
        if (dt > ROOTVSMALL)
        {
            p.setCellValues(cloud, ttd);
            p.calcDispersion(cloud, ttd, dt);
            if (solution.cellValueSourceCorrection())
            {
                p.cellValueSourceCorrection(cloud, ttd, dt);
            }
            p.calc(cloud, ttd, dt);
        }
        p.age() += dt;
        cloud.functions().postMove(p, dt, start, ttd.keepParticle);
    }
    return true;
}


template<class ParcelType>
void Foam::LazyTrackingParcel<ParcelType>::trackDrift()
{
    if (drift_ != vector::zero)
    {
        // Within the cell by construction: only tet faces are crossed,
        // the step fraction stays
        this->track(drift_, 0);
        if (this->onBoundaryFace())
        {
            FatalErrorInFunction
                << "Lazy tracking of parcel (origProc " << this->origProc()
                << ", origId " << this->origId() << ") reached boundary face "
                << this->face() << " with its drift " << drift_
                << ": this is a bug" << abort(FatalError);
        }
        drift_ = Zero;
    }
    centreValid_ = false;
    allowedDrift_ = -1;
}


template<class ParcelType>
void Foam::LazyTrackingParcel<ParcelType>::transformProperties
(
    const tensor& T
)
{
    ParcelType::transformProperties(T);
    drift_ = transform(T, drift_);
    centreValid_ = false;
}


template<class ParcelType>
void Foam::LazyTrackingParcel<ParcelType>::transformProperties
(
    const vector& separation
)
{
    ParcelType::transformProperties(separation);
    centreValid_ = false;
}


// * * * * * * * * * * * * * * IOStream operators  * * * * * * * * * * * * * //

#include "LazyTrackingParcelIO.C"

// ************************************************************************* //
