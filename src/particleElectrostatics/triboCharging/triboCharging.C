/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "triboCharging.H"
#include "mathematicalConstants.H"
#include "error.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;

//- Stop with "<quantity> = <value> is out of range: it must be <range>"
[[noreturn]] void outOfRange
(
    const char* func,
    const char* quantity,
    const scalar value,
    const char* range
)
{
    FatalErrorIn(func)
        << quantity << " = " << value
        << " is out of range: it must be " << range
        << Foam::exit(Foam::FatalError);

    ::abort();  // not reached
}


inline void checkFinite(const char* func, const char* quantity, scalar x)
{
    if (!std::isfinite(x))
    {
        outOfRange(func, quantity, x, "finite");
    }
}


inline void checkPositive(const char* func, const char* quantity, scalar x)
{
    if (!(x > 0) || !std::isfinite(x))
    {
        outOfRange(func, quantity, x, "finite and > 0");
    }
}


inline void checkNonNegative(const char* func, const char* quantity, scalar x)
{
    if (!(x >= 0) || !std::isfinite(x))
    {
        outOfRange(func, quantity, x, "finite and >= 0");
    }
}


inline void checkPoisson(const char* func, const char* quantity, scalar nu)
{
    if (!(nu > -1 && nu <= 0.5))
    {
        outOfRange(func, quantity, nu, "in (-1, 0.5]");
    }
}


//- A charging efficiency from measured data: finite and >= 0, else an
//  error saying which signs disagree
scalar checkedKappa
(
    const char* func,
    const scalar kappa,
    const char* denominator
)
{
    if (!std::isfinite(kappa))
    {
        outOfRange(func, "Charging efficiency kappa_c", kappa, "finite");
    }
    if (kappa < 0)
    {
        FatalErrorIn(func)
            << "Charging efficiency kappa_c = " << kappa
            << " is out of range: it must be >= 0." << Foam::nl
            << "    The measured dq and " << denominator
            << " have opposite signs: check the signs of the charges"
            << Foam::exit(Foam::FatalError);
    }
    return kappa;
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

// Out-of-line definitions (C++11/14: needed when bound to a reference)
constexpr Foam::scalar Foam::triboCharging::eps0;
constexpr Foam::scalar Foam::triboCharging::elementaryCharge;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::triboCharging::triboCharging(const scalar kappaC, const scalar Gamma)
:
    kappaC_(kappaC),
    Gamma_(Gamma)
{
    checkNonNegative(FUNCTION_NAME, "Charging efficiency kappa_c", kappaC);
    checkFinite(FUNCTION_NAME, "Charge transfer limitation Gamma [V/m]", Gamma);
}


// * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * * //

Foam::scalar Foam::triboCharging::chargeTransfer
(
    const scalar dA,
    const scalar kappaC,
    const scalar Gamma,
    const scalar En
)
{
    checkFinite(FUNCTION_NAME, "Contact area increment dA [m^2]", dA);
    checkNonNegative(FUNCTION_NAME, "Charging efficiency kappa_c", kappaC);
    checkFinite(FUNCTION_NAME, "Charge transfer limitation Gamma [V/m]", Gamma);
    checkFinite(FUNCTION_NAME, "Contact field E.n [V/m]", En);

    // Rasera Eq. (16), on loading only (see the class description)
    if (dA <= 0)
    {
        return 0;
    }
    return dA*kappaC*eps0*(Gamma - En);
}


Foam::scalar Foam::triboCharging::chargeDensity
(
    const scalar kappaC,
    const scalar Gamma,
    const scalar En
)
{
    checkNonNegative(FUNCTION_NAME, "Charging efficiency kappa_c", kappaC);
    checkFinite(FUNCTION_NAME, "Charge transfer limitation Gamma [V/m]", Gamma);
    checkFinite(FUNCTION_NAME, "Contact field E.n [V/m]", En);

    // Rasera Eq. (14) with the lumped Gamma of Eq. (16)
    return kappaC*eps0*(Gamma - En);
}


Foam::scalar Foam::triboCharging::surfaceField(const scalar q, const scalar r)
{
    checkFinite(FUNCTION_NAME, "Particle charge q [C]", q);
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);

    return q/(4*pi*eps0*r*r);
}


Foam::scalar Foam::triboCharging::GammaFromWorkFunctions
(
    const scalar phiI,
    const scalar phiJ,
    const scalar deltaE
)
{
    checkFinite(FUNCTION_NAME, "Work function phi_i [J]", phiI);
    checkFinite(FUNCTION_NAME, "Work function phi_j [J]", phiJ);
    checkPositive
    (
        FUNCTION_NAME,
        "Charge transfer cutoff distance delta_e [m]",
        deltaE
    );

    // Rasera Eqs. (14)-(15), electrons from the lower work function to
    // the higher (the printed phi_i - phi_j reversed: see the header)
    return (phiJ - phiI)/(deltaE*elementaryCharge);
}


Foam::scalar Foam::triboCharging::GammaFromSaturationCharge
(
    const scalar qSat,
    const scalar r
)
{
    checkFinite(FUNCTION_NAME, "Saturation charge q_sat [C]", qSat);
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);

    // Rasera Eq. (17)
    return qSat/(4*pi*eps0*r*r);
}


Foam::scalar Foam::triboCharging::GammaFromSaturationChargeDensity
(
    const scalar sigmaSat
)
{
    checkFinite
    (
        FUNCTION_NAME,
        "Saturation charge density sigma_sat [C/m^2]",
        sigmaSat
    );

    // Rasera Eq. (17)
    return sigmaSat/eps0;
}


Foam::scalar Foam::triboCharging::GammaFromSaturationChargeDensity
(
    const scalar sigmaSatI,
    const scalar sigmaSatJ
)
{
    checkFinite
    (
        FUNCTION_NAME,
        "Saturation charge density sigma_i,sat [C/m^2]",
        sigmaSatI
    );
    checkFinite
    (
        FUNCTION_NAME,
        "Saturation charge density sigma_j,sat [C/m^2]",
        sigmaSatJ
    );

    // Rasera Eq. (18)
    return (sigmaSatI - sigmaSatJ)/eps0;
}


Foam::scalar Foam::triboCharging::GammaSaturationModel
(
    const scalar sigmaF,
    const scalar PhiSat,
    const scalar r
)
{
    checkFinite
    (
        FUNCTION_NAME,
        "Plane saturation charge density sigma_f [C/m^2]",
        sigmaF
    );
    checkFinite
    (
        FUNCTION_NAME,
        "Surface potential at saturation Phi_sat [V]",
        PhiSat
    );
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);

    // Rasera Eq. (19), left-hand side read as sigma_sat/eps0
    return sigmaF/eps0 + PhiSat/r;
}


void Foam::triboCharging::fitSaturationModel
(
    const UList<scalar>& r,
    const UList<scalar>& Gamma,
    scalar& sigmaF,
    scalar& PhiSat
)
{
    if (r.size() != Gamma.size())
    {
        FatalErrorInFunction
            << "Number of radii " << r.size()
            << " differs from the number of Gamma values " << Gamma.size()
            << exit(FatalError);
    }

    // Linear least squares of Gamma = a + b x, x = 1/r (Eq. 19)
    const label n = r.size();
    scalar mx = 0, my = 0;
    forAll(r, i)
    {
        checkPositive(FUNCTION_NAME, "Particle radius r [m]", r[i]);
        checkFinite
        (
            FUNCTION_NAME,
            "Charge transfer limitation Gamma [V/m]",
            Gamma[i]
        );
        mx += 1/r[i];
        my += Gamma[i];
    }
    if (n > 0)
    {
        mx /= n;
        my /= n;
    }

    scalar sxx = 0, sxy = 0;
    forAll(r, i)
    {
        const scalar dx = 1/r[i] - mx;
        sxx += dx*dx;
        sxy += dx*(Gamma[i] - my);
    }

    if (n < 2 || !(sxx > 0))
    {
        FatalErrorInFunction
            << "Number of distinct particle radii = "
            << (n < 2 ? n : 1) << " is out of range: Eq. (19) needs"
            << " Gamma at >= 2 different radii, got r = " << r
            << exit(FatalError);
    }

    PhiSat = sxy/sxx;
    sigmaF = eps0*(my - PhiSat*mx);
}


Foam::scalar Foam::triboCharging::kappaFromTransfer
(
    const scalar dq,
    const scalar dA,
    const scalar Gamma,
    const scalar En
)
{
    checkFinite(FUNCTION_NAME, "Measured charge transfer dq [C]", dq);
    checkPositive(FUNCTION_NAME, "Contact area dA [m^2]", dA);
    checkFinite(FUNCTION_NAME, "Charge transfer limitation Gamma [V/m]", Gamma);
    checkFinite(FUNCTION_NAME, "Contact field E.n [V/m]", En);
    if (Gamma == En)
    {
        outOfRange
        (
            FUNCTION_NAME,
            "Driving field Gamma - E.n [V/m]",
            0,
            "non-zero (no transfer at saturation: kappa_c undetermined)"
        );
    }

    // Rasera Eq. (16) solved for kappa_c
    return checkedKappa
    (
        FUNCTION_NAME,
        dq/(dA*eps0*(Gamma - En)),
        "Gamma - E.n"
    );
}


Foam::scalar Foam::triboCharging::kappaWall
(
    const scalar dq,
    const scalar dA,
    const scalar r,
    const scalar qSat,
    const scalar qI
)
{
    checkFinite(FUNCTION_NAME, "Measured charge transfer dq [C]", dq);
    checkPositive(FUNCTION_NAME, "Contact area dA [m^2]", dA);
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);
    checkFinite(FUNCTION_NAME, "Saturation charge q_sat [C]", qSat);
    checkFinite(FUNCTION_NAME, "Initial charge q_i [C]", qI);
    if (qSat == qI)
    {
        outOfRange
        (
            FUNCTION_NAME,
            "q_sat - q_i [C]",
            0,
            "non-zero (a saturated particle does not charge: kappa_c"
            " undetermined)"
        );
    }

    // Rasera Eq. (20)
    return checkedKappa
    (
        FUNCTION_NAME,
        4*pi*r*r*dq/(dA*(qSat - qI)),
        "q_sat - q_i"
    );
}


Foam::scalar Foam::triboCharging::kappaPair
(
    const scalar dq,
    const scalar dA,
    const scalar rI,
    const scalar qSatI,
    const scalar qI,
    const scalar rJ,
    const scalar qSatJ,
    const scalar qJ
)
{
    checkFinite(FUNCTION_NAME, "Measured charge transfer dq [C]", dq);
    checkPositive(FUNCTION_NAME, "Contact area dA [m^2]", dA);
    checkPositive(FUNCTION_NAME, "Particle radius r_i [m]", rI);
    checkPositive(FUNCTION_NAME, "Particle radius r_j [m]", rJ);
    checkFinite(FUNCTION_NAME, "Saturation charge q_i,sat [C]", qSatI);
    checkFinite(FUNCTION_NAME, "Saturation charge q_j,sat [C]", qSatJ);
    checkFinite(FUNCTION_NAME, "Initial charge q_i [C]", qI);
    checkFinite(FUNCTION_NAME, "Initial charge q_j [C]", qJ);

    const scalar d = rJ*rJ*(qSatI - qI) - rI*rI*(qSatJ - qJ);
    if (d == 0)
    {
        outOfRange
        (
            FUNCTION_NAME,
            "r_j^2 (q_i,sat - q_i) - r_i^2 (q_j,sat - q_j) [C m^2]",
            0,
            "non-zero (no driving field: kappa_c undetermined)"
        );
    }

    // Rasera Eq. (21)
    return checkedKappa
    (
        FUNCTION_NAME,
        4*pi*rI*rI*rJ*rJ*dq/(dA*d),
        "r_j^2 (q_i,sat - q_i) - r_i^2 (q_j,sat - q_j)"
    );
}


Foam::scalar Foam::triboCharging::kappaLikePair
(
    const scalar dq,
    const scalar dA,
    const scalar r,
    const scalar dq0
)
{
    checkFinite(FUNCTION_NAME, "Measured charge transfer dq [C]", dq);
    checkPositive(FUNCTION_NAME, "Contact area dA [m^2]", dA);
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);
    checkFinite(FUNCTION_NAME, "Charge difference q_j - q_i [C]", dq0);
    if (dq0 == 0)
    {
        outOfRange
        (
            FUNCTION_NAME,
            "Charge difference q_j - q_i [C]",
            0,
            "non-zero (like particles of equal charge do not charge)"
        );
    }

    // Rasera Eq. (22)
    return checkedKappa
    (
        FUNCTION_NAME,
        4*pi*r*r*dq/(dA*dq0),
        "q_j - q_i"
    );
}


Foam::scalar Foam::triboCharging::kappaLikePair
(
    const scalar dA,
    const scalar r
)
{
    checkPositive(FUNCTION_NAME, "Contact area dA [m^2]", dA);
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);

    // Rasera Eq. (23)
    return 4*pi*r*r/dA;
}


Foam::scalar Foam::triboCharging::GammaKappa(const scalar dq, const scalar dA)
{
    checkFinite(FUNCTION_NAME, "Measured charge transfer dq [C]", dq);
    checkPositive(FUNCTION_NAME, "Contact area dA [m^2]", dA);

    // Rasera Eq. (24)
    return dq/(dA*eps0);
}


Foam::scalar Foam::triboCharging::sphereMass(const scalar r, const scalar rho)
{
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);
    checkPositive(FUNCTION_NAME, "Particle density rho [kg/m^3]", rho);

    return 4.0/3.0*pi*r*r*r*rho;
}


Foam::scalar Foam::triboCharging::effectiveRadius
(
    const scalar rI,
    const scalar rJ
)
{
    checkPositive(FUNCTION_NAME, "Particle radius r_i [m]", rI);
    checkPositive(FUNCTION_NAME, "Particle radius r_j [m]", rJ);

    // Rasera Eq. (5)
    return rI*rJ/(rI + rJ);
}


Foam::scalar Foam::triboCharging::effectiveMass
(
    const scalar mI,
    const scalar mJ
)
{
    checkPositive(FUNCTION_NAME, "Particle mass m_i [kg]", mI);
    checkPositive(FUNCTION_NAME, "Particle mass m_j [kg]", mJ);

    // Rasera Eq. (10)
    return mI*mJ/(mI + mJ);
}


Foam::scalar Foam::triboCharging::effectiveModulus
(
    const scalar YI,
    const scalar nuI,
    const scalar YJ,
    const scalar nuJ
)
{
    checkPositive(FUNCTION_NAME, "Young's modulus Y_i [Pa]", YI);
    checkPoisson(FUNCTION_NAME, "Poisson's ratio nu_i", nuI);
    checkPositive(FUNCTION_NAME, "Young's modulus Y_j [Pa]", YJ);
    checkPoisson(FUNCTION_NAME, "Poisson's ratio nu_j", nuJ);

    // Rasera Eq. (6) with G = Y/(2(1 + nu)): (1 - nu)/(2G) = (1 - nu^2)/Y
    return 1/((1 - nuI*nuI)/YI + (1 - nuJ*nuJ)/YJ);
}


Foam::scalar Foam::triboCharging::effectiveModulus
(
    const scalar YI,
    const scalar nuI
)
{
    checkPositive(FUNCTION_NAME, "Young's modulus Y_i [Pa]", YI);
    checkPoisson(FUNCTION_NAME, "Poisson's ratio nu_i", nuI);

    // Rasera Eq. (6), rigid wall (Y_j -> infinity)
    return YI/(1 - nuI*nuI);
}


Foam::scalar Foam::triboCharging::contactArea
(
    const scalar rStar,
    const scalar delta
)
{
    checkPositive(FUNCTION_NAME, "Effective radius r* [m]", rStar);
    checkFinite(FUNCTION_NAME, "Overlap delta [m]", delta);

    // Rasera section 2.2 (below Eq. 15): A = pi r* delta, zero if apart
    return delta > 0 ? pi*rStar*delta : 0;
}


Foam::scalar Foam::triboCharging::hertzMaxOverlap
(
    const scalar mStar,
    const scalar rStar,
    const scalar YStar,
    const scalar vn
)
{
    checkPositive(FUNCTION_NAME, "Effective mass m* [kg]", mStar);
    checkPositive(FUNCTION_NAME, "Effective radius r* [m]", rStar);
    checkPositive(FUNCTION_NAME, "Effective modulus Y* [Pa]", YStar);
    checkNonNegative(FUNCTION_NAME, "Normal impact speed v_n [m/s]", vn);

    // Energy balance of the Hertz force, Rasera Eq. (4):
    // (1/2) m* vn^2 = (8/15) Y* sqrt(r*) delta_max^(5/2)
    return pow(15*mStar*vn*vn/(16*YStar*sqrt(rStar)), 0.4);
}


Foam::scalar Foam::triboCharging::hertzMaxContactArea
(
    const scalar mStar,
    const scalar rStar,
    const scalar YStar,
    const scalar vn
)
{
    return contactArea(rStar, hertzMaxOverlap(mStar, rStar, YStar, vn));
}


Foam::scalar Foam::triboCharging::maxContactAreaWall
(
    const scalar r,
    const scalar rho,
    const scalar Y,
    const scalar nu,
    const scalar vn
)
{
    checkPositive(FUNCTION_NAME, "Particle radius r [m]", r);
    checkPositive(FUNCTION_NAME, "Particle density rho [kg/m^3]", rho);
    checkPositive(FUNCTION_NAME, "Young's modulus Y [Pa]", Y);
    checkPoisson(FUNCTION_NAME, "Poisson's ratio nu", nu);
    checkNonNegative(FUNCTION_NAME, "Normal impact speed v_n [m/s]", vn);

    // Rasera Eq. (25)
    return
        4*pi*r*r
       *pow(5*pi/128*rho*(1 - nu*nu)/Y, 0.4)
       *pow(vn, 0.8);
}


Foam::scalar Foam::triboCharging::maxContactAreaPair
(
    const scalar mI,
    const scalar rI,
    const scalar YI,
    const scalar nuI,
    const scalar mJ,
    const scalar rJ,
    const scalar YJ,
    const scalar nuJ,
    const scalar vn
)
{
    const scalar mStar = effectiveMass(mI, mJ);
    const scalar YStar = effectiveModulus(YI, nuI, YJ, nuJ);
    checkPositive(FUNCTION_NAME, "Particle radius r_i [m]", rI);
    checkPositive(FUNCTION_NAME, "Particle radius r_j [m]", rJ);
    checkNonNegative(FUNCTION_NAME, "Normal impact speed v_n [m/s]", vn);

    // Rasera Eq. (26) as printed
    return
        pi
       *pow(15*sqrt(2.0)/32*mStar/YStar, 0.4)
       *pow(2*rI*rJ/(rI + rJ), 0.8)
       *pow(vn, 0.8);
}


// ************************************************************************* //
