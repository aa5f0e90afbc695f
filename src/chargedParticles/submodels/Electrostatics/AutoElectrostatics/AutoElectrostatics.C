/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "AutoElectrostatics.H"
#include "ElectrostaticsSurvey.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
void Foam::AutoElectrostatics<CloudType>::store
(
    const word& scene,
    const dictionary& dict
)
{
    dictionary state;
    state.add("rung", rungName_);
    state.add("rmsError", rungError_);
    state.add("scene", scene);
    state.add
    (
        "parcels",
        returnReduce(this->owner().size(), sumOp<label>())
    );
    state.add("model", dict);
    this->owner().outputProperties().set("electrostaticsAuto", state);
}


template<class CloudType>
void Foam::AutoElectrostatics<CloudType>::choose()
{
    ElectrostaticsSurvey<CloudType> survey(this->owner(), this->coeffDict());
    survey.run(dictionary());
    survey.write(Info);

    label k = survey.recommended();
    if (k < 0)
    {
        k = survey.mostAccurate();
        WarningInFunction
            << "electrostaticsModel auto: no rung meets autoCoeffs/accuracy "
            << survey.accuracy() << "; taking the most accurate, "
            << survey.rungs()[k].name << " (rms force error "
            << survey.rungs()[k].rmsError << ")" << endl;
    }
    const auto& r = survey.rungs()[k];
    rung_ = ElectrostaticsModel<CloudType>::New(r.dict, this->owner());
    rungName_ = r.name;
    rungError_ = r.rmsError;
    sinceChoice_ = 0;
    Info<< "Electrostatics auto: " << rungName_ << " (rms force error "
        << 100*rungError_ << " % against "
        << survey.referenceName() << ", " << 1e3*r.cost
        << " ms per evaluation)" << nl << endl;

    store
    (
        ElectrostaticsSurvey<CloudType>::sceneKindNames[survey.kind()],
        r.dict
    );
}


template<class CloudType>
bool Foam::AutoElectrostatics<CloudType>::restore()
{
    const dictionary& props = this->owner().outputProperties();
    if (!props.isDict("electrostaticsAuto"))
    {
        return false;
    }
    const dictionary& state = props.subDict("electrostaticsAuto");

    ElectrostaticsSurvey<CloudType> survey(this->owner(), this->coeffDict());
    const word scene
    (
        ElectrostaticsSurvey<CloudType>::sceneKindNames[survey.classify()]
    );
    const label n = returnReduce(this->owner().size(), sumOp<label>());
    const label n0 = state.get<label>("parcels");
    if (scene != state.get<word>("scene") || 2*n < n0 || n > 2*n0)
    {
        Info<< "Electrostatics auto: the scene changed since the choice of "
            << state.get<word>("rung") << " (" << state.get<word>("scene")
            << ", " << n0 << " parcels; now " << scene << ", " << n
            << "): measuring the rungs again" << endl;
        return false;
    }

    rung_ = ElectrostaticsModel<CloudType>::New
    (
        state.subDict("model"),
        this->owner()
    );
    rungName_ = state.get<word>("rung");
    rungError_ = state.get<scalar>("rmsError");
    sinceChoice_ = 0;
    Info<< "Electrostatics auto: keeps " << rungName_ << " (rms force error "
        << 100*rungError_ << " %, chosen before the restart; scene "
        << scene << ", " << n << " parcels)" << nl << endl;
    return true;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::AutoElectrostatics<CloudType>::AutoElectrostatics
(
    const dictionary& dict,
    CloudType& owner
)
:
    ElectrostaticsModel<CloudType>(dict, owner, typeName),
    recheckInterval_
    (
        getCheckedOrDefault<label>
        (
            this->coeffDict(), "recheckInterval", 0,
            [](const label n) { return n >= 0; },
            ": it must be >= 0 (evaluations between measurements; 0: choose"
            " once)"
        )
    ),
    sinceChoice_(0),
    rung_(nullptr),
    rungName_(),
    rungError_(-1)
{
    // The survey's entries are checked now, not at the first step
    ElectrostaticsSurvey<CloudType>(owner, this->coeffDict());
    Info<< "    The cheapest far-field rung within the accuracy, measured"
        << " on the parcels at the first evaluation" << endl;
}


template<class CloudType>
Foam::AutoElectrostatics<CloudType>::AutoElectrostatics
(
    const AutoElectrostatics<CloudType>& em
)
:
    ElectrostaticsModel<CloudType>(em),
    recheckInterval_(em.recheckInterval_),
    sinceChoice_(em.sinceChoice_),
    rung_(em.rung_.valid() ? em.rung_->clone() : nullptr),
    rungName_(em.rungName_),
    rungError_(em.rungError_)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::AutoElectrostatics<CloudType>::calculate()
{
    if (!rung_.valid())
    {
        // Nothing to measure before a parcel is charged (contact charging
        // scenes start neutral): no far field until then
        bool charged = false;
        for (const auto& p : this->owner())
        {
            charged = charged || p.q() != 0;
        }
        if (!returnReduce(charged, orOp<bool>()))
        {
            for (auto& p : this->owner())
            {
                p.fE() = Zero;
                p.E() = Zero;
            }
            return;
        }
        if (!restore())
        {
            choose();
        }
    }
    else if (recheckInterval_ > 0 && ++sinceChoice_ >= recheckInterval_)
    {
        choose();
    }
    rung_->calculate();
}


template<class CloudType>
Foam::scalar Foam::AutoElectrostatics<CloudType>::mediumEpsilonR() const
{
    return
        rung_.valid()
      ? rung_->mediumEpsilonR()
      : this->coeffDict().template lookupOrDefault<scalar>("epsilonR", 1);
}


template<class CloudType>
bool Foam::AutoElectrostatics<CloudType>::readsCollisionRecords() const
{
    return this->owner().constProps().stiffnessRatio() < 1;
}


// ************************************************************************* //
