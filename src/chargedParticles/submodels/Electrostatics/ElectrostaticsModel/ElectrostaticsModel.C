/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ElectrostaticsModel.H"
#include "cpuTime.H"
#include "NearFieldModel.H"
#include "ListListOps.H"
#include "processorHalo.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::dictionary Foam::ElectrostaticsModel<CloudType>::withCoeffs
(
    const dictionary& dict,
    const word& type
)
{
    // All coefficients have defaults: <type>Coeffs may be omitted
    dictionary d(dict);
    if (!d.found(type + "Coeffs"))
    {
        d.add(word(type + "Coeffs"), dictionary());
    }
    return d;
}


template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::readLayers(const dictionary& dict)
{
    // The near field belongs to the far field's coefficients: a nearField
    // entry next to electrostaticsModel is a misplaced one
    if (dict.found("nearField"))
    {
        FatalIOErrorInFunction(dict)
            << "Entry nearField in " << dict.name().c_str() << " is"
            << " misplaced: the near field is selected in the far field's"
            << " coefficients, " << this->modelType() << "Coeffs { nearField"
            << " { type none|inducedDipole; } }" << exit(FatalIOError);
    }

    if (dict.found("appliedField"))
    {
        // A vector constant starts with '(', a Function1 with its type; a
        // number is a scalar given for a vector
        const ITstream& is = dict.lookup("appliedField");
        const token first(is.size() ? is[0] : token());
        if (!first.isWord() && !first.isPunctuation())
        {
            FatalIOErrorInFunction(dict)
                << "Entry appliedField in " << dict.name().c_str()
                << " must be a vector [V/m], e.g. (0 0 1e5), or a Function1"
                << " of time giving one (e.g. sine {...}); found " << first
                << exit(FatalIOError);
        }
        appliedField_ = Function1<vector>::New("appliedField", dict);
        const vector Ea0 =
            appliedField_->value(this->owner().db().time().value());
        if (!std::isfinite(mag(Ea0)))
        {
            FatalIOErrorInFunction(dict)
                << "Entry appliedField in " << dict.name().c_str()
                << " is not finite: " << Ea0 << exit(FatalIOError);
        }
        Info<< "    Applied field " << appliedField_->type() << ", "
            << Ea0 << " V/m now" << endl;
    }

    nearField_ = NearFieldModel<CloudType>::New
    (
        this->coeffDict(),
        this->owner()
    );
}


// * * * * * * * * * * * * Protected Member Functions  * * * * * * * * * * //

template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::gatherCharges
(
    List<pointField>& allX,
    List<scalarField>& allQ
) const
{
    allX.setSize(Pstream::nProcs());
    allQ.setSize(Pstream::nProcs());

    pointField& x = allX[Pstream::myProcNo()];
    scalarField& q = allQ[Pstream::myProcNo()];
    x.setSize(this->owner().size());
    q.setSize(this->owner().size());
    label i = 0;
    for (const auto& p : this->owner())
    {
        x[i] = p.centre();
        q[i] = p.q();
        ++i;
    }

    Pstream::gatherList(allX);
    Pstream::scatterList(allX);
    Pstream::gatherList(allQ);
    Pstream::scatterList(allQ);
}



template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::combine
(
    const List<pointField>& allX,
    const List<scalarField>& allQ,
    pointField& x,
    scalarField& q,
    label& myStart
)
{
    myStart = 0;
    for (label proci = 0; proci < Pstream::myProcNo(); ++proci)
    {
        myStart += allX[proci].size();
    }
    x = ListListOps::combine<pointField>(allX, accessOp<pointField>());
    q = ListListOps::combine<scalarField>(allQ, accessOp<scalarField>());
}


template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::gatherCharges
(
    pointField& x,
    scalarField& q,
    label& myStart
) const
{
    List<pointField> allX;
    List<scalarField> allQ;
    gatherCharges(allX, allQ);
    combine(allX, allQ, x, q, myStart);
}


template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::gatherHalo
(
    const scalar range,
    pointField& x,
    scalarField& q,
    labelList& ids
) const
{
    const label n = this->owner().size();
    pointField xLocal(n);
    scalarField qLocal(n);
    List<labelPair> keys(n);
    label i = 0;
    for (const auto& p : this->owner())
    {
        xLocal[i] = p.centre();
        qLocal[i] = p.q();
        keys[i] = labelPair(p.origProc(), p.origId());
        ++i;
    }

    // Unfolded across the cyclic patches: their copies within range too
    const polyMesh& mesh = this->owner().mesh();
    const processorHalo halo
    (
        processorHalo::processorBoxes(mesh),
        xLocal,
        range,
        processorHalo::cyclicTranslations(mesh),
        true
    );
    x = halo.points();
    halo.gather(qLocal);
    q.transfer(qLocal);
    halo.gather(keys);
    ids.setSize(2*keys.size());
    forAll(keys, j)
    {
        ids[2*j] = keys[j].first();
        ids[2*j + 1] = keys[j].second();
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ElectrostaticsModel<CloudType>::ElectrostaticsModel(CloudType& owner)
:
    CloudSubModelBase<CloudType>(owner),
    appliedField_(nullptr),
    nearField_(NearFieldModel<CloudType>::New(dictionary(), owner)),
    Ea_(Zero),
    farFieldTime_(0),
    nearFieldTime_(0)
{}


template<class CloudType>
Foam::ElectrostaticsModel<CloudType>::ElectrostaticsModel
(
    const dictionary& dict,
    CloudType& owner,
    const word& type
)
:
    CloudSubModelBase<CloudType>(owner, withCoeffs(dict, type), typeName, type),
    appliedField_(nullptr),
    nearField_(nullptr),
    Ea_(Zero),
    farFieldTime_(0),
    nearFieldTime_(0)
{
    readLayers(dict);
}


template<class CloudType>
Foam::ElectrostaticsModel<CloudType>::ElectrostaticsModel
(
    const ElectrostaticsModel<CloudType>& em
)
:
    CloudSubModelBase<CloudType>(em),
    appliedField_(em.appliedField_.clone()),
    nearField_(em.nearField_->clone()),
    Ea_(em.Ea_),
    farFieldTime_(0),
    nearFieldTime_(0)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
bool Foam::ElectrostaticsModel<CloudType>::hasLayers() const
{
    return appliedField_.valid() || nearField_->active();
}


template<class CloudType>
bool Foam::ElectrostaticsModel<CloudType>::readsContacts() const
{
    return readsCollisionRecords() || nearField_->readsCollisionRecords();
}


template<class CloudType>
void Foam::ElectrostaticsModel<CloudType>::update()
{
    cpuTime timer;
    calculate();

    if (appliedField_.valid())
    {
        Ea_ = appliedField_->value(this->owner().db().time().value());
        for (auto& p : this->owner())
        {
            p.E() += Ea_;
            p.fE() += p.q()*Ea_;
        }
    }

    farFieldTime_ += timer.cpuTimeIncrement();

    if (nearField_->active())
    {
        nearField_->correct(*this);
        nearFieldTime_ += timer.cpuTimeIncrement();
    }
    else
    {
        // No torque or dipole without a near field (nor stale ones from
        // a restart)
        for (auto& p : this->owner())
        {
            p.tE() = Zero;
            p.dipole() = Zero;
        }
    }
}


template<class CloudType>
Foam::scalar Foam::ElectrostaticsModel<CloudType>::totalEnergy() const
{
    scalar e = energy();
    if (appliedField_.valid())
    {
        scalar eA = 0;
        for (const auto& p : this->owner())
        {
            eA -= p.q()*(Ea_ & p.centre());
        }
        e += returnReduce(eA, sumOp<scalar>());
    }
    if (nearField_->active())
    {
        e += nearField_->energy();
    }
    return e;
}


// * * * * * * * * * * * * * * * * Selectors * * * * * * * * * * * * * * * * //

template<class CloudType>
Foam::autoPtr<Foam::ElectrostaticsModel<CloudType>>
Foam::ElectrostaticsModel<CloudType>::New
(
    const dictionary& dict,
    CloudType& owner
)
{
    const word modelType
    (
        dict.template lookupOrDefault<word>("electrostaticsModel", "none")
    );

    Info<< "Selecting electrostatics model " << modelType << endl;

    auto cstrIter = dictionaryConstructorTablePtr_->cfind(modelType);

    if (!cstrIter.found())
    {
        FatalIOErrorInLookup
        (
            dict,
            "electrostaticsModel",
            modelType,
            *dictionaryConstructorTablePtr_
        ) << exit(FatalIOError);
    }

    return autoPtr<ElectrostaticsModel<CloudType>>(cstrIter()(dict, owner));
}


// ************************************************************************* //
