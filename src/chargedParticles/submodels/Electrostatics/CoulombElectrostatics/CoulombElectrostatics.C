/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "CoulombElectrostatics.H"
#include "keyedPoints.H"
#include "processorHalo.H"
#include "ListListOps.H"
#include "Pstream.H"
#include "inputLimits.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::CoulombElectrostatics<CloudType>::readEpsilonR
(
    const dictionary& coeffs
)
{
    // A medium's permittivity is at least the vacuum's (the near-field
    // kernels, e.g. BEM, take it so)
    return getCheckedOrDefault<scalar>
    (
        coeffs, "epsilonR", 1,
        [](const scalar e) { return e >= 1 && e <= inputLimits::large; },
        ": it must be finite and >= 1 (1: vacuum), at most "
      + Foam::name(inputLimits::large),
        " (relative permittivity of the medium)"
    );
}


template<class CloudType>
Foam::scalar Foam::CoulombElectrostatics<CloudType>::readCutoff
(
    const dictionary& coeffs
)
{
    const scalar rCut =
        coeffs.found("rCut") ? coeffs.get<scalar>("rCut") : -1;
    if (!(rCut > 0) || !std::isfinite(rCut))
    {
        FatalIOErrorInFunction(coeffs)
            << "Entry rCut (cutoff radius [m]) in "
            << coeffs.name().c_str() << " is "
            << (coeffs.found("rCut") ? "out of range" : "missing")
            << ": it must be given, finite and > 0" << exit(FatalIOError);
    }
    return rCut;
}


template<class CloudType>
void Foam::CoulombElectrostatics<CloudType>::gatherPairHalo
(
    pointField& xS,
    scalarField& qS,
    labelList& ids
) const
{
    this->gatherHalo
    (
        contactCorrection_ != 0 ? max(rCut_, contactRange()) : rCut_,
        xS, qS, ids
    );
}


template<class CloudType>
void Foam::CoulombElectrostatics<CloudType>::correctContactPairs
(
    const UList<point>& xS,
    const UList<scalar>& qS,
    const labelUList& ids,
    const label myStart,
    vectorField& f
) const
{
    // The contact partners named by the collision records, among the
    // sources by their (origProc, origId): the nearest instance (a partner
    // across a cyclic patch is its copy)
    const keyedPoints where(xS, ids);

    label i = 0;
    for (const auto& p : this->owner())
    {
        for (const auto& record : p.collisionRecords().pairRecords())
        {
            const label j = where.nearest
            (
                labelPair(record.origProcOfOther(), record.origIdOfOther()),
                xS[myStart + i]
            );
            if (j >= 0)
            {
                f[i] += contactCorrection_*coulomb_.pairForce
                (
                    xS[myStart + i], qS[myStart + i], xS[j], qS[j]
                );
            }
        }
        ++i;
    }
}


template<class CloudType>
Foam::scalar Foam::CoulombElectrostatics<CloudType>::contactRange() const
{
    // Two of the largest parcels touching: centres at most the sum of
    // their largest semi-axes apart
    scalar aMax = 0;
    for (const auto& p : this->owner())
    {
        aMax = max(aMax, cmptMax(p.semiAxes()));
    }
    return 2*returnReduce(aMax, maxOp<scalar>());
}


template<class CloudType>
void Foam::CoulombElectrostatics<CloudType>::setFields
(
    const List<pointField>& allX,
    const List<scalarField>& allQ,
    const vectorField& E
)
{
    // The field is kept (contact charging needs it, also on neutral
    // parcels); the force is q E
    vectorField f(allQ[Pstream::myProcNo()]*E);
    if (contactCorrection_ != 0)
    {
        // (origProc, origId) of every parcel of every processor
        List<labelList> allIds(Pstream::nProcs());
        labelList& ids = allIds[Pstream::myProcNo()];
        ids.setSize(2*this->owner().size());
        label i = 0;
        for (const auto& p : this->owner())
        {
            ids[2*i] = p.origProc();
            ids[2*i + 1] = p.origId();
            ++i;
        }
        Pstream::gatherList(allIds);
        Pstream::scatterList(allIds);

        pointField xS;
        scalarField qS;
        label myStart = 0;
        this->combine(allX, allQ, xS, qS, myStart);
        correctContactPairs
        (
            xS, qS,
            ListListOps::combine<labelList>(allIds, accessOp<labelList>()),
            myStart, f
        );
    }
    setFields(E, f);
}


template<class CloudType>
void Foam::CoulombElectrostatics<CloudType>::setFields
(
    const UList<point>& xS,
    const UList<scalar>& qS,
    const labelUList& ids,
    const vectorField& E
)
{
    vectorField f(E.size());
    forAll(f, i)
    {
        f[i] = qS[i]*E[i];
    }
    if (contactCorrection_ != 0)
    {
        correctContactPairs(xS, qS, ids, 0, f);
    }
    setFields(E, f);
}


template<class CloudType>
void Foam::CoulombElectrostatics<CloudType>::setFields
(
    const vectorField& E,
    const vectorField& f
)
{
    label i = 0;
    for (auto& p : this->owner())
    {
        p.E() = E[i];
        p.fE() = f[i];
        ++i;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::CoulombElectrostatics<CloudType>::CoulombElectrostatics
(
    const dictionary& dict,
    CloudType& owner,
    const word& type,
    const bool cutoff
)
:
    ElectrostaticsModel<CloudType>(dict, owner, type),
    coulomb_(readEpsilonR(this->coeffDict())),
    contactCorrection_
    (
        Foam::pow(owner.constProps().stiffnessRatio(), 0.4)
      - 1
    ),
    rCut_(cutoff ? readCutoff(this->coeffDict()) : -1)
{
    // The pairs through a cyclic patch come from the copies shifted by
    // one period (gatherHalo): all of them while rCut is at most the
    // shortest period
    const scalar period =
        cutoff ? processorHalo::shortestCyclicPeriod(owner.mesh()) : GREAT;
    if (rCut_ > period)
    {
        FatalIOErrorInFunction(this->coeffDict())
            << "Entry rCut = " << rCut_ << " in "
            << this->coeffDict().name().c_str() << " exceeds the "
            << "cyclic period " << period << " of the mesh: it must be "
            << "in (0, " << period << "]" << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::CoulombElectrostatics<CloudType>::CoulombElectrostatics
(
    const CoulombElectrostatics<CloudType>& em
)
:
    ElectrostaticsModel<CloudType>(em),
    coulomb_(em.coulomb_),
    contactCorrection_(em.contactCorrection_),
    rCut_(em.rCut_)
{}


// ************************************************************************* //
