/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ParticleHistory.H"
#include "Pstream.H"
#include "ListOps.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::ParticleHistory<CloudType>::openFile()
{
    if (!Pstream::master() || filePtr_.valid())
    {
        return;
    }

    const Time& time = this->owner().db().time();
    const fileName dir =
        this->outputDir()/time.timeName(time.startTime().value());
    mkDir(dir);

    filePtr_.reset(new OFstream(dir/"particleHistory.dat"));
    OFstream& os = filePtr_();
    os.precision(17);
    os  << "# Particle history of cloud " << this->owner().name() << nl
        << "# time origProc origId x y z Ux Uy Uz d rho q fEx fEy fEz"
        << " omegax omegay omegaz qw qx qy qz tEx tEy tEz px py pz"
        << nl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ParticleHistory<CloudType>::ParticleHistory
(
    const dictionary& dict,
    CloudType& owner,
    const word& modelName
)
:
    CloudFunctionObject<CloudType>(dict, owner, modelName, typeName),
    interval_
    (
        getCheckedOrDefault<label>
        (
            this->coeffDict(), "interval", 1,
            [](const label n) { return n >= 1; },
            ": it must be >= 1"
        )
    ),
    maxOrigId_
    (
        this->coeffDict().template lookupOrDefault<label>("maxOrigId", -1)
    ),
    filePtr_()
{}


template<class CloudType>
Foam::ParticleHistory<CloudType>::ParticleHistory
(
    const ParticleHistory<CloudType>& ph
)
:
    CloudFunctionObject<CloudType>(ph),
    interval_(ph.interval_),
    maxOrigId_(ph.maxOrigId_),
    filePtr_()
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::ParticleHistory<CloudType>::postEvolve()
{
    const Time& time = this->owner().db().time();
    if (time.timeIndex() % interval_ != 0)
    {
        return;
    }

    // Local rows: the two labels and the nv scalars of each parcel
    const label nv = 25;
    label np = 0;
    for (const auto& p : this->owner())
    {
        if (maxOrigId_ < 0 || p.origId() <= maxOrigId_)
        {
            ++np;
        }
    }
    const label me = Pstream::myProcNo();
    List<labelList> ids(Pstream::nProcs());
    List<scalarList> values(Pstream::nProcs());
    ids[me].setSize(2*np);
    values[me].setSize(nv*np);

    label i = 0;
    for (const auto& p : this->owner())
    {
        if (maxOrigId_ >= 0 && p.origId() > maxOrigId_)
        {
            continue;
        }
        ids[me][2*i] = p.origProc();
        ids[me][2*i + 1] = p.origId();
        const point x = p.centre();
        scalar* v = &values[me][nv*i];
        for (direction c = 0; c < 3; ++c)
        {
            v[c] = x[c];
            v[3 + c] = p.U()[c];
            v[9 + c] = p.fE()[c];
        }
        v[6] = p.d();
        v[7] = p.rho();
        v[8] = p.q();
        const vector omega = p.omega();
        const quaternion& o = p.orientation();
        v[15] = o.w();
        for (direction c = 0; c < 3; ++c)
        {
            v[12 + c] = omega[c];
            v[16 + c] = o.v()[c];
            v[19 + c] = p.tE()[c];
            v[22 + c] = p.dipole()[c];
        }
        ++i;
    }

    Pstream::gatherList(ids);
    Pstream::gatherList(values);

    if (!Pstream::master())
    {
        return;
    }

    openFile();

    // Rows of all processors, sorted by (origProc, origId)
    DynamicList<label> procOf, rowOf;
    DynamicList<scalar> keys;
    forAll(ids, proci)
    {
        for (label r = 0; r < ids[proci].size()/2; ++r)
        {
            procOf.append(proci);
            rowOf.append(r);
            // origId < 2^31 and origProc small: exact in a double
            keys.append
            (
                scalar(ids[proci][2*r])*scalar(labelMax)
              + scalar(ids[proci][2*r + 1])
            );
        }
    }
    labelList order;
    sortedOrder(keys, order);

    OFstream& os = filePtr_();
    for (const label k : order)
    {
        const label proci = procOf[k];
        const label r = rowOf[k];
        os  << time.value() << ' ' << ids[proci][2*r] << ' '
            << ids[proci][2*r + 1];
        for (label c = 0; c < nv; ++c)
        {
            os  << ' ' << values[proci][nv*r + c];
        }
        os  << nl;
    }
    os.flush();
}


// ************************************************************************* //
