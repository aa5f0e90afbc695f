/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactLaw.H"
#include "checkedEntry.H"
#include "inputLimits.H"

// * * * * * * * * * * * * * * * Local Functions  * * * * * * * * * * * * * //

namespace
{

//- The part of run-time selection table Part named modelType (the
//  dictionary's entry `entry`), constructed from dict
template<class Part>
Foam::autoPtr<Part> selectPart
(
    const Foam::dictionary& dict,
    const char* entry,
    const Foam::word& modelType
)
{
    auto* table = Part::dictionaryConstructorTablePtr_;
    auto cstrIter = table->cfind(modelType);
    if (!cstrIter.found())
    {
        FatalIOErrorInLookup(dict, entry, modelType, *table)
            << Foam::exit(Foam::FatalIOError);
    }
    return Foam::autoPtr<Part>(cstrIter()(dict));
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::contactLaw::contactLaw
(
    const dictionary& dict,
    const contactLaw* parent
)
:
    normal_
    (
        selectPart<normalContactLaw>
        (
            dict,
            "normalModel",
            dict.getOrDefault<word>
            (
                "normalModel",
                parent ? parent->normal().type() : word("hertzDashpot")
            )
        )
    ),
    tangential_
    (
        selectPart<tangentialContactLaw>
        (
            dict,
            "tangentialModel",
            dict.getOrDefault<word>
            (
                "tangentialModel",
                parent ? parent->tangential().type() : word("mindlin")
            )
        )
    ),
    rolling_
    (
        selectPart<rollingContactLaw>
        (
            dict,
            "rollingModel",
            dict.getOrDefault<word>
            (
                "rollingModel",
                parent ? parent->rolling().type() : word("constantTorque")
            )
        )
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::contactProperties Foam::contactLaw::properties
(
    const scalar E1, const scalar nu1,
    const scalar E2, const scalar nu2,
    const dictionary& dict,
    const scalar eDefault,
    const scalar muDefault,
    const scalar muRDefault
) const
{
    const scalar large = inputLimits::large;
    auto nonNegative = [large](const scalar x) { return x >= 0 && x <= large; };
    const std::string nonNegativeRange
    (
        ": it must be >= 0, at most " + Foam::name(large)
    );

    contactProperties p;

    // Below 1e-6 the damping ratio is beyond the bracket of the dashpot's
    // calibration (|beta| = 1000; e = 1e-6 is |beta| = 500), whose bisection
    // then integrates endless creeping contacts
    p.e = getCheckedOrDefault<scalar>
    (
        dict, "e", eDefault,
        [](const scalar x) { return x >= 1e-6 && x <= 1; },
        " [1e-06, 1] (1e-06: a perfectly plastic contact)",
        " (restitution coefficient)"
    );
    p.mu = getCheckedOrDefault<scalar>
    (
        dict, "mu", muDefault, nonNegative, nonNegativeRange,
        " (friction coefficient)"
    );
    p.muR = getCheckedOrDefault<scalar>
    (
        dict, "rollingFriction", muRDefault, nonNegative, nonNegativeRange
    );

    // Ruan Eq. (38)
    p.Estar = 1/((1 - sqr(nu1))/E1 + (1 - sqr(nu2))/E2);

    // Rasera Eq. (12) with G = E/(2(1 + nu))
    const scalar G1 = E1/(2*(1 + nu1));
    const scalar G2 = E2/(2*(1 + nu2));
    p.Gstar = 1/((2 - nu1)/G1 + (2 - nu2)/G2);

    p.beta = normal_->dampingRatio(p.e);
    return p;
}


// ************************************************************************* //
