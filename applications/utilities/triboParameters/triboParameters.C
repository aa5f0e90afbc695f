/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
-------------------------------------------------------------------------------
Application
    triboParameters

Group
    grpPreProcessingUtilities

Description
    Charging parameters Gamma [V/m] and kappa_c [-] of the tribocharging
    model of Rasera 2022 (Powder Technol. 117607, Eq. 16) from single-contact
    experiments, as in Rasera section 2.2 (Eqs. 17-26) and Tables 1-4, with
    the intermediate contact mechanics (max. overlap, contact area).

    Reads system/triboParametersDict of the case, or the file given with
    -dict (any path). Every sub-dictionary of "entries" is one experiment:

        contact         wall;       // wall | particle (two spheres)
        diameter        3.18e-3;    // [m] or: radius
        rho             2150;       // [kg/m^3] > 0
        E               0.564e9;    // Young's modulus [Pa] > 0
        nu              0.42;       // Poisson's ratio (-1, 0.5]
        impactVelocity  2.56;       // normal (relative) impact speed [m/s] > 0

        // Gamma, one of (particle i):
        qSat            -6.57e-10;  // saturation charge [C], Eq. (17)
        sigmaSat        -2.07e-5;   // saturation charge density [C/m^2]
        workFunctions               // Eqs. (14)-(15)
        {
            phiI    4.7;            // [eV]
            phiJ    4.3;            // [eV]
            deltaE  500e-9;         // charge transfer cutoff distance [m] > 0
        }

        // kappa_c:
        dq              -2.70e-11;  // measured transfer of one contact [C]
        q0              -1.71e-10;  // charge before the contact [C], default 0

        // contact wall, optional: the wall's E, nu (rigid when absent;
        // used by contactAreaModel hertz only, Eq. 25 has a rigid wall)
        wall { E 69e9; nu 0.33; }

        // contact particle: like particles unless "partner" is given
        chargeDifference 8.02e-13;  // q_j - q_i [C], like particles, Eq. (22);
                                    // without it and dq: Eq. (23)
        partner                     // dissimilar particle j, Eq. (21); each
        {                           // entry defaults to particle i's
            diameter 4e-3; rho 1140; E 1.27e9; nu 0.49;
            qSat -1e-11;            // or sigmaSat (required for Eq. 21)
            q0 0;
        }

        reference { Gamma -2.34e6; kappaC 9.64; }  // optional: paper values,
                                                   // printed with rel. diff.

    Top level: contactAreaModel paper | hertz (default paper), also per
    entry:
      - paper: maximum contact area of Eq. (25) (sphere on a rigid wall) or
        Eq. (26) (two spheres, as printed);
      - hertz: pi r* delta_max, delta_max from the energy balance of the
        Hertz force Eq. (4), r*, Y*, m* of Eqs. (5), (6), (10) (with the
        wall's E, nu when given). Equal to Eq. (25) for a rigid wall; Eq.
        (26) is 2^0.6 times larger than this.

    Gamma: Eq. (17) (wall: q_sat/(4 pi eps0 r^2) or sigma_sat/eps0), Eq. (18)
    (particles: (sigma_i,sat - sigma_j,sat)/eps0, zero for like particles),
    Eqs. (14)-(15) from work functions.
    kappa_c: Eq. (20) (wall with q_sat), Eq. (16) solved for kappa_c with
    E.n = q0/(4 pi eps0 r^2) (wall with work functions), Eq. (22) (like
    particles), Eq. (23) (like particles, no dq), Eq. (21) (partner).

    Missing or out-of-range entries stop with a FatalIOError naming the
    entry and its allowed range.

Usage
    triboParameters [-dict <file>] [-case <dir>]

\*---------------------------------------------------------------------------*/

#include "readUtilityDict.H"
#include "argList.H"
#include "dictionary.H"
#include "triboCharging.H"
#include "mathematicalConstants.H"

#include <cstdio>
#include <string>

using namespace Foam;
using constant::mathematical::pi;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Stop with "Entry <key> = <value> in <dict> is out of range: <range>"
[[noreturn]] void badEntry
(
    const dictionary& dict,
    const word& key,
    const scalar value,
    const char* range
)
{
    FatalIOErrorInFunction(dict)
        << "Entry " << key << " = " << value << " in "
        << dict.name().c_str() << " is out of range: it must be " << range
        << exit(FatalIOError);

    ::abort();  // not reached
}


scalar readFinite(const dictionary& dict, const word& key)
{
    const scalar x = dict.get<scalar>(key);
    if (!std::isfinite(x))
    {
        badEntry(dict, key, x, "finite");
    }
    return x;
}


scalar readPositive(const dictionary& dict, const word& key)
{
    const scalar x = dict.get<scalar>(key);
    if (!(x > 0) || !std::isfinite(x))
    {
        badEntry(dict, key, x, "finite and > 0");
    }
    return x;
}


scalar readPoisson(const dictionary& dict, const word& key)
{
    const scalar x = dict.get<scalar>(key);
    if (!(x > -1 && x <= 0.5))
    {
        badEntry(dict, key, x, "in (-1, 0.5]");
    }
    return x;
}


//- Exactly one of the keys a, b present (neither allowed if optional)
//  Returns 0 for none, 1 for a, 2 for b
int oneOf
(
    const dictionary& dict,
    const word& a,
    const word& b,
    const bool optional
)
{
    const bool hasA = dict.found(a);
    const bool hasB = dict.found(b);
    if (hasA && hasB)
    {
        FatalIOErrorInFunction(dict)
            << "Entries " << a << " and " << b << " are both given in "
            << dict.name().c_str() << ": give only one of them"
            << exit(FatalIOError);
    }
    if (!hasA && !hasB && !optional)
    {
        FatalIOErrorInFunction(dict)
            << "Entry " << a << " or " << b << " is missing in "
            << dict.name().c_str() << exit(FatalIOError);
    }
    return hasA ? 1 : (hasB ? 2 : 0);
}


//- A sphere of the experiment, entries defaulting to those of "base"
struct sphere
{
    scalar r = 0;
    scalar rho = 0;
    scalar E = 0;
    scalar nu = 0;
    scalar q0 = 0;
    bool hasSat = false;
    scalar qSat = 0;

    scalar mass() const
    {
        return triboCharging::sphereMass(r, rho);
    }

    scalar sigmaSat() const
    {
        return qSat/(4*pi*r*r);
    }
};


sphere readSphere(const dictionary& dict, const sphere* base)
{
    sphere s;
    if (base)
    {
        s = *base;
    }

    const int size = oneOf(dict, "radius", "diameter", base != nullptr);
    if (size == 1)
    {
        s.r = readPositive(dict, "radius");
    }
    else if (size == 2)
    {
        s.r = 0.5*readPositive(dict, "diameter");
    }

    if (!base || dict.found("rho")) s.rho = readPositive(dict, "rho");
    if (!base || dict.found("E")) s.E = readPositive(dict, "E");
    if (!base || dict.found("nu")) s.nu = readPoisson(dict, "nu");
    if (dict.found("q0")) s.q0 = readFinite(dict, "q0");
    else if (!base) s.q0 = 0;

    // Saturation charge or density (Eq. 17): needs the radius
    const int sat = oneOf(dict, "qSat", "sigmaSat", true);
    if (sat == 1)
    {
        s.hasSat = true;
        s.qSat = readFinite(dict, "qSat");
    }
    else if (sat == 2)
    {
        s.hasSat = true;
        s.qSat = readFinite(dict, "sigmaSat")*4*pi*s.r*s.r;
    }
    else if (base && size)
    {
        // a partner of another size inherits the density, not the charge
        s.qSat = base->sigmaSat()*4*pi*s.r*s.r;
    }
    return s;
}


//- Results of one entry
struct result
{
    word name;
    word contact;
    word areaModel;
    scalar r = 0, vn = 0, mStar = 0, rStar = 0, YStar = 0;
    scalar deltaMax = 0, AHertz = 0, Amax = 0;
    scalar Gamma = 0, kappaC = 0;
    std::string eqs;
    bool hasRef = false;
    scalar GammaRef = 0, kappaRef = 0;
};


//- The Hertz overlap at the impact speed (Rasera Eq. 4 with r*, Y*, m*)
//  and its contact area pi r* delta_max, into res
void hertzContact(result& res)
{
    res.deltaMax = triboCharging::hertzMaxOverlap
    (
        res.mStar, res.rStar, res.YStar, res.vn
    );
    res.AHertz = triboCharging::contactArea(res.rStar, res.deltaMax);
}


//- A particle against a wall: contact mechanics (Eq. 4 or 25) into res;
//  returns the largest contact area
scalar wallContact
(
    const word& name,
    const dictionary& dict,
    const sphere& pI,
    const bool hertz,
    result& res
)
{
    scalar A = 0;
    res.mStar = pI.mass();
    res.rStar = pI.r;
    bool rigid = true;
    if (dict.found("wall"))
    {
        const dictionary& w = dict.subDict("wall");
        rigid = false;
        res.YStar = triboCharging::effectiveModulus
        (
            pI.E, pI.nu, readPositive(w, "E"), readPoisson(w, "nu")
        );
        if (!hertz)
        {
            WarningInFunction
                << "Entry " << name << ": the wall's E and nu are not"
                << " used by Eq. (25) (rigid wall); set"
                << " contactAreaModel hertz to use them" << endl;
        }
    }
    if (rigid || !hertz)
    {
        res.YStar = triboCharging::effectiveModulus(pI.E, pI.nu);
    }
    hertzContact(res);
    A = hertz
      ? res.AHertz
      : triboCharging::maxContactAreaWall
        (
            pI.r, pI.rho, pI.E, pI.nu, res.vn
        );
    res.eqs = hertz ? "A: Hertz Eq.4" : "A: Eq.25";
    return A;
}


//- A particle against a particle: contact mechanics (Eq. 4 or 26), Gamma
//  (Eq. 18 or 15) and kappa_c (Eqs. 21-23) into res; returns the largest
//  contact area
scalar pairContact
(
    const dictionary& dict,
    const sphere& pI,
    const bool hertz,
    const bool hasWF,
    const scalar GammaWF,
    result& res
)
{
    const scalar mI = pI.mass();
    scalar A = 0;
    const bool like = !dict.found("partner");
    const sphere pJ =
        like ? pI : readSphere(dict.subDict("partner"), &pI);
    const scalar mJ = pJ.mass();

    res.mStar = triboCharging::effectiveMass(mI, mJ);
    res.rStar = triboCharging::effectiveRadius(pI.r, pJ.r);
    res.YStar = triboCharging::effectiveModulus(pI.E, pI.nu, pJ.E, pJ.nu);
    hertzContact(res);
    A = hertz
      ? res.AHertz
      : triboCharging::maxContactAreaPair
        (
            mI, pI.r, pI.E, pI.nu, mJ, pJ.r, pJ.E, pJ.nu, res.vn
        );
    res.eqs = hertz ? "A: Hertz Eq.4" : "A: Eq.26";

    // Gamma: Eq. (18) or work functions; kappa_c: Eqs. (21)-(23)
    if (hasWF)
    {
        res.Gamma = GammaWF;
        res.eqs += ", G: Eq.15";
    }
    else if (like)
    {
        res.Gamma = 0;
        res.eqs += ", G: Eq.18 (like)";
    }
    else
    {
        if (!pI.hasSat && !pJ.hasSat)
        {
            FatalIOErrorInFunction(dict)
                << "Entry qSat or sigmaSat is missing in "
                << dict.name().c_str() << " (and its partner): Gamma of"
                << " unlike particles needs saturation data (Eq. 18) or"
                << " workFunctions" << exit(FatalIOError);
        }
        res.Gamma = triboCharging::GammaFromSaturationChargeDensity
        (
            pI.sigmaSat(), pJ.sigmaSat()
        );
        res.eqs += ", G: Eq.18";
    }

    if (like)
    {
        const bool hasDq = dict.found("dq");
        const bool hasDiff = dict.found("chargeDifference");
        if (hasDq != hasDiff)
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << (hasDq ? "chargeDifference" : "dq")
                << " is missing in " << dict.name().c_str()
                << ": Eq. (22) needs both dq and chargeDifference"
                << " (q_j - q_i); give neither for Eq. (23)"
                << exit(FatalIOError);
        }
        if (hasDq)
        {
            res.kappaC = triboCharging::kappaLikePair
            (
                readFinite(dict, "dq"),
                A,
                pI.r,
                readFinite(dict, "chargeDifference")
            );
            res.eqs += ", k: Eq.22";
        }
        else
        {
            res.kappaC = triboCharging::kappaLikePair(A, pI.r);
            res.eqs += ", k: Eq.23";
        }
    }
    else
    {
        res.kappaC = triboCharging::kappaPair
        (
            readFinite(dict, "dq"),
            A,
            pI.r, pI.qSat, pI.q0,
            pJ.r, pJ.qSat, pJ.q0
        );
        res.eqs += ", k: Eq.21";
    }
    return A;
}


//- A particle against a wall: Gamma (Eq. 17 or 14-15) and kappa_c (Eq. 20
//  or 16) into res
void wallCharging
(
    const dictionary& dict,
    const sphere& pI,
    const bool hasWF,
    const scalar GammaWF,
    const scalar A,
    result& res
)
{
    const scalar dq = readFinite(dict, "dq");
    if (pI.hasSat)
    {
        res.Gamma = triboCharging::GammaFromSaturationCharge(pI.qSat, pI.r);
        res.kappaC = triboCharging::kappaWall(dq, A, pI.r, pI.qSat, pI.q0);
        res.eqs += ", G: Eq.17, k: Eq.20";
    }
    else if (hasWF)
    {
        res.Gamma = GammaWF;
        res.kappaC = triboCharging::kappaFromTransfer
        (
            dq, A, res.Gamma, triboCharging::surfaceField(pI.q0, pI.r)
        );
        res.eqs += ", G: Eq.15, k: Eq.16";
    }
    else
    {
        FatalIOErrorInFunction(dict)
            << "Entry qSat, sigmaSat or workFunctions is missing in "
            << dict.name().c_str() << ": one of them gives Gamma"
            << " (Eq. 17 or Eqs. 14-15)" << exit(FatalIOError);
    }
}


result evaluate
(
    const word& name,
    const dictionary& dict,
    const word& defaultAreaModel
)
{
    result res;
    res.name = name;

    res.contact = dict.get<word>("contact");
    if (res.contact != "wall" && res.contact != "particle")
    {
        FatalIOErrorInFunction(dict)
            << "Entry contact = " << res.contact << " in "
            << dict.name().c_str() << " is unknown: valid are wall, particle"
            << exit(FatalIOError);
    }
    const bool wall = (res.contact == "wall");

    res.areaModel =
        dict.getOrDefault<word>("contactAreaModel", defaultAreaModel);
    if (res.areaModel != "paper" && res.areaModel != "hertz")
    {
        FatalIOErrorInFunction(dict)
            << "Entry contactAreaModel = " << res.areaModel << " in "
            << dict.name().c_str() << " is unknown: valid are paper, hertz"
            << exit(FatalIOError);
    }
    const bool hertz = (res.areaModel == "hertz");

    const sphere pI = readSphere(dict, nullptr);
    res.r = pI.r;
    res.vn = readPositive(dict, "impactVelocity");

    // Work functions (Eqs. 14-15), optional
    const bool hasWF = dict.found("workFunctions");
    scalar GammaWF = 0;
    if (hasWF)
    {
        const dictionary& wf = dict.subDict("workFunctions");
        GammaWF = triboCharging::GammaFromWorkFunctions
        (
            readFinite(wf, "phiI")*triboCharging::elementaryCharge,
            readFinite(wf, "phiJ")*triboCharging::elementaryCharge,
            readPositive(wf, "deltaE")
        );
    }
    if (hasWF && pI.hasSat)
    {
        FatalIOErrorInFunction(dict)
            << "Entries workFunctions and qSat/sigmaSat are both given in "
            << dict.name().c_str() << ": give only one source of Gamma"
            << exit(FatalIOError);
    }

    // Contact mechanics, then the wall's charging parameters (the
    // pair's come with its mechanics)
    const scalar A =
        wall
      ? wallContact(name, dict, pI, hertz, res)
      : pairContact(dict, pI, hertz, hasWF, GammaWF, res);
    res.Amax = A;
    if (wall)
    {
        wallCharging(dict, pI, hasWF, GammaWF, A, res);
    }

    if (dict.found("reference"))
    {
        const dictionary& ref = dict.subDict("reference");
        res.hasRef = true;
        res.GammaRef = readFinite(ref, "Gamma");
        res.kappaRef = readFinite(ref, "kappaC");
    }

    return res;
}


//- Fixed-width scientific number
std::string sci(const scalar x, const int width = 11, const int prec = 4)
{
    char buf[64];
    std::snprintf(buf, sizeof(buf), "%*.*e", width, prec, x);
    return buf;
}


//- Left-aligned padded text
std::string pad(const std::string& s, const size_t width)
{
    return s.size() >= width ? s + " " : s + std::string(width - s.size(), ' ');
}


//- Right-aligned padded text
std::string rpad(const std::string& s, const size_t width)
{
    return s.size() >= width ? s : std::string(width - s.size(), ' ') + s;
}


//- Relative difference to a reference; the absolute one for a zero reference
std::string rel(const scalar x, const scalar ref)
{
    if (ref == 0)
    {
        return sci(x - ref, 7, 1) + " abs";
    }
    return sci((x - ref)/ref, 10, 2);
}

//- Every experiment of entries (errors named by their entry)
List<result> evaluateAll
(
    const dictionary& entries,
    const word& areaModel,
    const fileName& dictFile
)
{
    List<result> results;
    for (const entry& e : entries)
    {
        if (!e.isDict())
        {
            FatalIOErrorInFunction(entries)
                << "Entry " << e.keyword() << " in "
                << entries.name().c_str() << " is not a dictionary: each"
                << " experiment is a sub-dictionary of entries"
                << exit(FatalIOError);
        }

        // Errors of the kernel (e.g. a negative kappa_c from the data) are
        // reported with the entry they come from
        const bool throwing = FatalError.throwExceptions(true);
        try
        {
            results.append(evaluate(e.keyword(), e.dict(), areaModel));
        }
        catch (const Foam::error& err)
        {
            FatalError.throwExceptions(throwing);
            FatalIOErrorInFunction(e.dict())
                << "Entry " << e.keyword() << " in " << dictFile << ":" << nl
                << "    " << err.message().c_str()
                << exit(FatalIOError);
        }
        FatalError.throwExceptions(throwing);
    }

    return results;
}


//- The two tables: contact mechanics and charging parameters
void printTables(const List<result>& results, const fileName& dictFile)
{
    Info<< "Dictionary: " << dictFile << nl
        << "eps0 = " << sci(triboCharging::eps0, 0, 10).c_str()
        << " F/m (CODATA 2018)" << nl
        << nl << "Contact mechanics (r*, Y*, m*: Rasera Eqs. 5, 6, 10;"
        << " delta_max: Hertz Eq. 4; A_max: the contactAreaModel)" << nl;

    size_t w = 12;
    for (const result& r : results)
    {
        w = max(w, r.name.size() + 2);
    }

    Info<< pad("entry", w).c_str() << pad("contact", 9).c_str()
        << rpad("r [m]", 11).c_str() << rpad("v_n [m/s]", 11).c_str()
        << rpad("m* [kg]", 12).c_str() << rpad("r* [m]", 12).c_str()
        << rpad("Y* [Pa]", 12).c_str() << rpad("dmax [m]", 11).c_str()
        << rpad("pi r* dmax", 13).c_str() << rpad("A_max [m^2]", 13).c_str()
        << "  model" << nl;
    for (const result& r : results)
    {
        Info<< pad(r.name, w).c_str() << pad(r.contact, 9).c_str()
            << sci(r.r).c_str() << sci(r.vn).c_str()
            << sci(r.mStar, 12).c_str() << sci(r.rStar, 12).c_str()
            << sci(r.YStar, 12).c_str() << sci(r.deltaMax, 11).c_str()
            << sci(r.AHertz, 13).c_str() << sci(r.Amax, 13).c_str()
            << "  " << r.areaModel.c_str() << nl;
    }

    Info<< nl << "Charging parameters (dq = dA kappa_c eps0 (Gamma - E.n),"
        << " Rasera Eq. 16)" << nl
        << pad("entry", w).c_str()
        << rpad("Gamma [V/m]", 11).c_str() << rpad("kappa_c [-]", 13).c_str()
        << rpad("Gamma*kappa_c", 15).c_str() << rpad("ref Gamma", 11).c_str()
        << rpad("rel.diff", 11).c_str() << rpad("ref kappa_c", 14).c_str()
        << rpad("rel.diff", 11).c_str() << "    equations" << nl;
    for (const result& r : results)
    {
        Info<< pad(r.name, w).c_str()
            << sci(r.Gamma).c_str() << sci(r.kappaC, 13).c_str()
            << sci(r.Gamma*r.kappaC, 15).c_str();
        if (r.hasRef)
        {
            Info<< sci(r.GammaRef, 11, 2).c_str() << " "
                << rel(r.Gamma, r.GammaRef).c_str()
                << sci(r.kappaRef, 14, 3).c_str() << " "
                << rel(r.kappaC, r.kappaRef).c_str();
        }
        else
        {
            Info<< pad("", 47).c_str();
        }
        Info<< "    " << r.eqs.c_str() << nl;
    }
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

int main(int argc, char *argv[])
{
    argList::addNote
    (
        "Tribocharging parameters Gamma and kappa_c (Rasera 2022, Eqs. 17-26)"
        " from single-contact experiments listed in a dictionary."
    );
    argList::noParallel();
    argList::noFunctionObjects();
    addUtilityDictOption("triboParameters");

    argList args(argc, argv);

    fileName dictFile;
    const dictionary dict(readUtilityDict(args, "triboParameters", dictFile));

    const word areaModel = dict.getOrDefault<word>("contactAreaModel", "paper");
    const dictionary& entries = dict.subDict("entries");

    const List<result> results(evaluateAll(entries, areaModel, dictFile));
    if (results.empty())
    {
        FatalIOErrorInFunction(entries)
            << "Dictionary " << entries.name().c_str()
            << " has no experiments" << exit(FatalIOError);
    }

    printTables(results, dictFile);

    Info<< nl << "End" << nl << endl;

    return 0;
}


// ************************************************************************* //
