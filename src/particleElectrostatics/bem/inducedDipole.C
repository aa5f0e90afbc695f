/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "inducedDipole.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "error.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

Foam::vector Foam::inducedDipole::depolarisationFactors(const vector& s)
{
    // L_k = abc/2 int_0^inf ds/((s + a_k^2) R_s), R_s = sqrt(prod(s + a^2))
    // (Eq. 50); s = m^2 tan^2(t) maps [0, inf) to [0, pi/2), composite
    // Simpson, the integrand vanishes at pi/2
    const scalar m2 = sqr(cmptMin(s));
    const label n = 20000;
    const scalar h = 0.5*pi/n;
    vector L(Zero);
    for (label i = 0; i < n; ++i)   // i = n contributes zero
    {
        const scalar t = i*h;
        const scalar w = (i == 0) ? 1 : ((i % 2) ? 4 : 2);
        const scalar tn = Foam::tan(t);
        const scalar sv = m2*tn*tn;
        const scalar ds = 2*m2*tn*(1 + tn*tn);
        const scalar Rs = Foam::sqrt
        (
            (sv + sqr(s.x()))*(sv + sqr(s.y()))*(sv + sqr(s.z()))
        );
        for (direction k = 0; k < 3; ++k)
        {
            L[k] += w*ds/((sv + sqr(s[k]))*Rs);
        }
    }
    return (s.x()*s.y()*s.z()/2)*(h/3)*L;
}


Foam::tensor Foam::inducedDipole::polarisability
(
    const vector& semiAxes,
    const tensor& R,
    const scalar kappaP,
    const scalar kappa0
)
{
    const vector L = depolarisationFactors(semiAxes);
    const scalar kt = kappaP/kappa0;
    const scalar V =
        4*pi*semiAxes.x()*semiAxes.y()*semiAxes.z()/3;
    const scalar c = pairwiseCoulomb::vacuumPermittivity*kappa0*V;
    tensor Ab(Zero);
    for (direction k = 0; k < 3; ++k)
    {
        Ab(k, k) = c*(kt - 1)/(1 + (kt - 1)*L[k]);
    }
    return R & Ab & R.T();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::inducedDipole::inducedDipole
(
    const scalar kappa0,
    const scalar tolerance,
    const label maxIter
)
:
    kappa0_(kappa0),
    tolerance_(tolerance),
    maxIter_(maxIter),
    Eext_(Zero),
    energy_(0),
    iterations_(0)
{
    if (!(kappa0 >= 1) || !(tolerance > 0) || maxIter < 1)
    {
        FatalErrorInFunction
            << "kappa0 = " << kappa0 << " (>= 1), tolerance = " << tolerance
            << " (> 0), maxIter = " << maxIter << " (>= 1) out of range"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::inducedDipole::addParticle
(
    const point& centre,
    const vector& semiAxes,
    const tensor& R,
    const scalar kappaP,
    const scalar q
)
{
    if (cmptMin(semiAxes) <= 0 || !(kappaP >= 1))
    {
        FatalErrorInFunction
            << "semiAxes " << semiAxes << " must be > 0 and kappaP "
            << kappaP << " >= 1" << exit(FatalError);
    }
    x_.append(centre);
    q_.append(q);
    alpha_.append(polarisability(semiAxes, R, kappaP, kappa0_));
    return x_.size() - 1;
}


Foam::label Foam::inducedDipole::solve()
{
    const label n = x_.size();
    const scalar k = 1/(4*pi*pairwiseCoulomb::vacuumPermittivity*kappa0_);
    p_.setSize(n);
    p_ = Zero;
    E_.setSize(n);

    auto field = [&](const label i)
    {
        vector E = Eext_;
        for (label j = 0; j < n; ++j)
        {
            if (j == i) continue;
            const vector r = x_[i] - x_[j];
            const scalar r2 = magSqr(r);
            const scalar ir3 = 1/(r2*Foam::sqrt(r2));
            E += k*q_[j]*ir3*r
               + k*(3*(p_[j] & r)/r2*r - p_[j])*ir3;
        }
        return E;
    };

    iterations_ = 0;
    for (label it = 0; it < maxIter_; ++it)
    {
        scalar dmax = 0, pmax = 0;
        for (label i = 0; i < n; ++i)
        {
            E_[i] = field(i);
        }
        for (label i = 0; i < n; ++i)
        {
            const vector pn = alpha_[i] & E_[i];
            dmax = max(dmax, mag(pn - p_[i]));
            pmax = max(pmax, mag(pn));
            p_[i] = pn;
        }
        iterations_ = it + 1;
        if (dmax <= tolerance_*pmax)
        {
            break;
        }
    }
    if (iterations_ == maxIter_)
    {
        WarningInFunction
            << "induced dipoles not converged in " << maxIter_
            << " iterations" << endl;
    }
    for (label i = 0; i < n; ++i)
    {
        E_[i] = field(i);
    }

    // Forces (Eq. 45), torques, energy
    F_.setSize(n);
    M_.setSize(n);
    energy_ = 0;
    for (label i = 0; i < n; ++i)
    {
        tensor G(Zero);   // G_ab = d_a E_b
        scalar phi = 0;
        for (label j = 0; j < n; ++j)
        {
            if (j == i) continue;
            const vector r = x_[i] - x_[j];
            const scalar r2 = magSqr(r);
            const scalar ir = 1/Foam::sqrt(r2);
            const scalar ir3 = ir/r2, ir5 = ir3/r2, ir7 = ir5/r2;
            const vector& p = p_[j];
            const scalar pr = p & r;
            G += k*q_[j]*(ir3*tensor::I - 3*ir5*(r*r));
            G += k*
            (
                3*ir5*((p*r) + (r*p) + pr*tensor::I)
              - 15*pr*ir7*(r*r)
            );
            phi += k*(q_[j]*ir + pr*ir3);
        }
        F_[i] = q_[i]*E_[i] + (p_[i] & G);
        M_[i] = p_[i] ^ E_[i];
        energy_ += 0.5*q_[i]*phi;
    }
    return iterations_;
}


// ************************************************************************* //
