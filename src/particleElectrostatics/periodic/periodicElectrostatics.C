/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "periodicElectrostatics.H"
#include "ewaldSum.H"
#include "quasiPeriodicDirect.H"
#include "pseudoParticle.H"
#include "p3m.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "Pstream.H"
#include "ListListOps.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Static data * * * * * * * * * * * * * * //

const Foam::scalar Foam::periodicForceError::binEdges[6] =
    {0.01, 0.05, 0.10, 0.20, 0.50, GREAT};


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::periodicElectrostatics::periodicElectrostatics
(
    const vector& L,
    const scalar epsilonR
)
:
    L_(L),
    invL_
    (
        L.x() > 0 ? 1/L.x() : 0,
        L.y() > 0 ? 1/L.y() : 0,
        L.z() > 0 ? 1/L.z() : 0
    ),
    epsilonR_(epsilonR),
    k_(pairwiseCoulomb(epsilonR).k())   // checks epsilonR
{
    for (direction d = 0; d < 3; ++d)
    {
        if (!(L[d] > 0) || !std::isfinite(L[d]))
        {
            FatalErrorInFunction
                << "Box edge L = " << L << " is out of range: every"
                << " component must be finite and > 0"
                << exit(FatalError);
        }
    }
}


Foam::autoPtr<Foam::periodicElectrostatics>
Foam::periodicElectrostatics::New(const dictionary& dict)
{
    const word method(dict.get<word>("method"));

    if (method == "ewald")
    {
        return autoPtr<periodicElectrostatics>(new ewaldSum(dict));
    }
    else if (method == "direct")
    {
        return autoPtr<periodicElectrostatics>(new quasiPeriodicDirect(dict));
    }
    else if (method == "pseudoParticle")
    {
        return autoPtr<periodicElectrostatics>(new pseudoParticle(dict));
    }
    else if (method == "p3m")
    {
        return autoPtr<periodicElectrostatics>(new p3m(dict));
    }

    FatalIOErrorInFunction(dict)
        << "Unknown method " << method << " in entry 'method'" << nl
        << "    Valid methods: (ewald direct pseudoParticle p3m)"
        << exit(FatalIOError);

    return nullptr;
}


// * * * * * * * * * * * * * * * Static helpers  * * * * * * * * * * * * * * //

Foam::vector Foam::periodicElectrostatics::readBox(const dictionary& dict)
{
    vector L;
    const entry& e = dict.lookupEntry("L", keyType::LITERAL);
    ITstream& is = e.stream();
    token t(is);
    if (t.isNumber())
    {
        L = vector::uniform(t.number());
    }
    else
    {
        is.putBack(t);
        is >> L;
    }
    for (direction d = 0; d < 3; ++d)
    {
        if (!(L[d] > 0) || !std::isfinite(L[d]))
        {
            FatalIOErrorInFunction(dict)
                << "Entry 'L' = " << L << " is out of range: the box edges"
                << " must be finite and > 0 (scalar for a cube or"
                << " (Lx Ly Lz))" << exit(FatalIOError);
        }
    }
    return L;
}


Foam::scalar Foam::periodicElectrostatics::readEpsilonR
(
    const dictionary& dict
)
{
    return readScalar(dict, "epsilonR", 1, 0, GREAT);
}


Foam::label Foam::periodicElectrostatics::readLabel
(
    const dictionary& dict,
    const word& key,
    const label deflt,
    const label lo,
    const label hi
)
{
    const label v = dict.getOrDefault<label>(key, deflt);
    if (v < lo || v > hi)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << v << " is out of range ["
            << lo << ", " << hi << "]" << exit(FatalIOError);
    }
    return v;
}


Foam::scalar Foam::periodicElectrostatics::readScalar
(
    const dictionary& dict,
    const word& key,
    const scalar deflt,
    const scalar lo,
    const scalar hi
)
{
    const scalar v = dict.getOrDefault<scalar>(key, deflt);
    if (!(v > lo) || !(v <= hi) || !std::isfinite(v))
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << key << "' = " << v << " is out of range ("
            << lo << ", " << hi << "]" << exit(FatalIOError);
    }
    return v;
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * * //

void Foam::periodicElectrostatics::checkInput
(
    const UList<point>& x,
    const UList<scalar>& q
) const
{
    if (x.size() != q.size())
    {
        FatalErrorInFunction
            << method() << ": " << x.size() << " positions but " << q.size()
            << " charges" << exit(FatalError);
    }
    forAll(x, i)
    {
        if
        (
            !std::isfinite(x[i].x()) || !std::isfinite(x[i].y())
         || !std::isfinite(x[i].z()) || !std::isfinite(q[i])
        )
        {
            FatalErrorInFunction
                << method() << ": charge " << i << " has a non-finite"
                << " position " << x[i] << " or charge " << q[i]
                << exit(FatalError);
        }
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::periodicElectrostatics::gatherAll
(
    const UList<point>& x,
    const UList<scalar>& q,
    pointField& allX,
    scalarField& allQ,
    label& myStart
)
{
    List<pointField> procX(Pstream::nProcs());
    List<scalarField> procQ(Pstream::nProcs());
    procX[Pstream::myProcNo()] = x;
    procQ[Pstream::myProcNo()] = q;
    Pstream::gatherList(procX);
    Pstream::scatterList(procX);
    Pstream::gatherList(procQ);
    Pstream::scatterList(procQ);
    myStart = 0;
    for (label proci = 0; proci < Pstream::myProcNo(); ++proci)
    {
        myStart += procX[proci].size();
    }
    allX = ListListOps::combine<pointField>(procX, accessOp<pointField>());
    allQ = ListListOps::combine<scalarField>(procQ, accessOp<scalarField>());
}


void Foam::periodicElectrostatics::computeDistributed
(
    const UList<point>& x,
    const UList<scalar>& q,
    const List<boundBox>& boxes,
    List<vector>& f
) const
{
    if (!Pstream::parRun())
    {
        compute(x, q, f);
        return;
    }

    pointField allX;
    scalarField allQ;
    label myStart;
    gatherAll(x, q, allX, allQ, myStart);
    List<vector> fAll;
    compute(allX, allQ, fAll);
    f = SubList<vector>(fAll, x.size(), myStart);
}


void Foam::periodicElectrostatics::potentials
(
    const UList<point>& x,
    const UList<scalar>& q,
    scalarField& phi
) const
{
    FatalErrorInFunction
        << "Method " << method() << " gives no potentials (p3m, direct do)"
        << exit(FatalError);
}


void Foam::periodicElectrostatics::potentialsDistributed
(
    const UList<point>& x,
    const UList<scalar>& q,
    const List<boundBox>& boxes,
    scalarField& phi
) const
{
    if (!Pstream::parRun())
    {
        potentials(x, q, phi);
        return;
    }

    pointField allX;
    scalarField allQ;
    label myStart;
    gatherAll(x, q, allX, allQ, myStart);
    scalarField phiAll;
    potentials(allX, allQ, phiAll);
    phi = SubList<scalar>(phiAll, x.size(), myStart);
}


Foam::scalar Foam::periodicElectrostatics::forceScale
(
    const UList<scalar>& q
) const
{
    if (q.empty())
    {
        return 0;
    }
    scalar q2 = 0;
    for (const scalar qi : q)
    {
        q2 += qi*qi;
    }
    const scalar n = q.size()/(L_.x()*L_.y()*L_.z());
    return k_*q2/q.size()*Foam::pow(n, 2.0/3.0);
}


void Foam::periodicElectrostatics::writeInfo(Ostream& os) const
{
    os  << method() << ": L = " << L_ << ", epsilonR = " << epsilonR_;
}


// * * * * * * * * * * * * * * * Error statistics  * * * * * * * * * * * * * //

Foam::periodicForceError::periodicForceError
(
    const UList<vector>& f,
    const UList<vector>& fRef,
    const labelUList& idx
)
:
    rmsAbs(0),
    rmsRef(0),
    median(0),
    p90(0)
{
    for (scalar& b : bins) b = 0;

    const label n = idx.empty() ? f.size() : idx.size();
    if (n == 0)
    {
        return;
    }

    std::vector<scalar> rel(n);
    for (label k = 0; k < n; ++k)
    {
        const label i = idx.empty() ? k : idx[k];
        const scalar e = mag(f[i] - fRef[i]);
        const scalar r = mag(fRef[i]);
        rmsAbs += e*e;
        rmsRef += r*r;
        rel[k] = (r > 0) ? e/r : (e > 0 ? GREAT : 0);
        label b = 0;
        while (b < 5 && rel[k] > binEdges[b]) ++b;
        bins[b] += 1;
    }
    for (scalar& b : bins) b /= n;
    rmsAbs = Foam::sqrt(rmsAbs/n);
    rmsRef = Foam::sqrt(rmsRef/n);

    std::sort(rel.begin(), rel.end());
    median = rel[n/2];
    p90 = rel[std::min(n - 1, (9*n)/10)];
}


void Foam::periodicForceError::write(Ostream& os) const
{
    os  << "rmsAbs/rmsRef " << rmsAbs/max(rmsRef, VSMALL)
        << " median " << median << " p90 " << p90 << " bins[%]";
    for (const scalar b : bins)
    {
        os  << ' ' << 100*b;
    }
}


Foam::tensor Foam::forceCovariance(const UList<vector>& f)
{
    if (f.empty())
    {
        return Zero;
    }
    vector mean(Zero);
    for (const vector& v : f) mean += v;
    mean /= f.size();

    tensor c(Zero);
    for (const vector& v : f)
    {
        const vector d = v - mean;
        c += d*d;   // outer product
    }
    return c/f.size();
}


// ************************************************************************* //
