/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "PeriodicCoulomb.H"
#include "cyclicPolyPatch.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::dictionary Foam::PeriodicCoulomb<CloudType>::kernelDict
(
    const dictionary& coeffs,
    const CloudType& owner
)
{
    dictionary d(coeffs);
    if (!d.found("method"))
    {
        d.add("method", word("p3m"));
    }
    if (!d.found("L"))
    {
        // The periodic box is the mesh (cyclic in x, y and z)
        d.add("L", owner.mesh().bounds().span());
    }

    label nCyclic = 0;
    for (const polyPatch& pp : owner.mesh().boundaryMesh())
    {
        if (isA<cyclicPolyPatch>(pp))
        {
            ++nCyclic;
        }
    }
    if (nCyclic < 6)
    {
        WarningInFunction
            << "electrostaticsModel periodic: the mesh has " << nCyclic
            << " cyclic patches; the forces are those of a tri-periodic box"
            << " of edges " << d.get<vector>("L") << endl;
    }
    return d;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::PeriodicCoulomb<CloudType>::PeriodicCoulomb
(
    const dictionary& dict,
    CloudType& owner
)
:
    ElectrostaticsModel<CloudType>(dict, owner, typeName),
    kernelDict_(kernelDict(this->coeffDict(), owner)),
    kernel_(periodicElectrostatics::New(kernelDict_))
{
    const scalar chi =
        owner.constProps().dict().template lookupOrDefault<scalar>
        (
            "stiffnessRatio",
            1
        );
    if (chi != 1)
    {
        FatalIOErrorInFunction(owner.constProps().dict())
            << "Entry stiffnessRatio = " << chi << " < 1 (reduced stiffness,"
            << " Ruan Eq. 44) is not supported by electrostaticsModel "
            << typeName << ": use 1 or directCoulomb" << exit(FatalIOError);
    }

    Info<< "    Tri-periodic electrostatics: ";
    kernel_->writeInfo(Info);
    Info<< endl;
}


template<class CloudType>
Foam::PeriodicCoulomb<CloudType>::PeriodicCoulomb
(
    const PeriodicCoulomb<CloudType>& em
)
:
    ElectrostaticsModel<CloudType>(em),
    kernelDict_(em.kernelDict_),
    kernel_(periodicElectrostatics::New(kernelDict_))
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::PeriodicCoulomb<CloudType>::calculate()
{
    List<pointField> allX;
    List<scalarField> allQ;
    this->gatherCharges(allX, allQ);

    // All processors' parcels in one list, this processor's first offset
    const label me = Pstream::myProcNo();
    label n = 0, offset = 0;
    forAll(allX, proci)
    {
        if (proci == me)
        {
            offset = n;
        }
        n += allX[proci].size();
    }
    pointField x(n);
    scalarField q(n);
    n = 0;
    forAll(allX, proci)
    {
        forAll(allX[proci], i)
        {
            x[n] = allX[proci][i];
            q[n] = allQ[proci][i];
            ++n;
        }
    }

    List<vector> f;
    kernel_->compute(x, q, f);

    label i = offset;
    for (auto& p : this->owner())
    {
        p.fE() = f[i];
        p.E() = p.q() != 0 ? f[i]/p.q() : vector::zero;
        ++i;
    }
}


template<class CloudType>
Foam::scalar Foam::PeriodicCoulomb<CloudType>::energy() const
{
    const ewaldSum* ewald = dynamic_cast<const ewaldSum*>(kernel_.get());
    if (!ewald)
    {
        return 0;
    }

    List<pointField> allX;
    List<scalarField> allQ;
    this->gatherCharges(allX, allQ);
    const pointField x(ListListOps::combine<pointField>(allX, accessOp<pointField>()));
    const scalarField q(ListListOps::combine<scalarField>(allQ, accessOp<scalarField>()));

    return ewald->energy(x, q);
}


// ************************************************************************* //
