/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "inducedDipole.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "cutoffPairs.H"

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
    const vector& L,
    const tensor& R,
    const scalar kappaP,
    const scalar kappa0
)
{
    // Body frame alpha_k = eps0 kappa0 V (kt - 1)/(1 + (kt - 1) L_k)
    // (Eq. 49 with Eq. 50's L); kt -> infinity: the conductor, V/L_k
    const scalar kt = kappaP/kappa0;
    const scalar V =
        4*pi*semiAxes.x()*semiAxes.y()*semiAxes.z()/3;
    const scalar c = pairwiseCoulomb::vacuumPermittivity*kappa0*V;
    tensor Ab(Zero);
    for (direction k = 0; k < 3; ++k)
    {
        Ab(k, k) =
            std::isfinite(kt)
          ? c*(kt - 1)/(1 + (kt - 1)*L[k])
          : c/L[k];
    }
    return R & Ab & R.T();
}


Foam::tensor Foam::inducedDipole::polarisability
(
    const vector& semiAxes,
    const tensor& R,
    const scalar kappaP,
    const scalar kappa0
)
{
    return polarisability
    (
        semiAxes, depolarisationFactors(semiAxes), R, kappaP, kappa0
    );
}


// * * * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * //

void Foam::inducedDipole::setSources()
{
    const label n = x_.size();
    // Sources: the particles and, in a periodic box, their images
    // within rNear of the particles' bounding box (rNear < L/2: each
    // pair is then met once from each side)
    DynamicList<point>& xS = xS_;
    DynamicList<label>& ofSource = ofSource_;
    xS = x_;
    ofSource = identity(n);
    if (cmptMax(period_) > 0 && n)
    {
        point lo(x_[0]), hi(x_[0]);
        for (const point& x : x_)
        {
            lo = min(lo, x);
            hi = max(hi, x);
        }
        for (direction d = 0; d < 3; ++d)
        {
            if (period_[d] > 0 && !(2*rNear_ < period_[d]))
            {
                FatalErrorInFunction
                    << "Near-field radius " << rNear_ << " must be below"
                    << " half the periodic box edge " << period_[d]
                    << exit(FatalError);
            }
        }
        for (label sx = -1; sx <= 1; ++sx)
        for (label sy = -1; sy <= 1; ++sy)
        for (label sz = -1; sz <= 1; ++sz)
        {
            const vector s
            (
                sx*period_.x(), sy*period_.y(), sz*period_.z()
            );
            if (s == vector::zero)
            {
                continue;
            }
            for (label j = 0; j < n; ++j)
            {
                const point xj = x_[j] + s;
                if
                (
                    cmptMin(xj - lo + vector::uniform(rNear_)) > 0
                 && cmptMin(hi - xj + vector::uniform(rNear_)) > 0
                )
                {
                    xS.append(xj);
                    ofSource.append(j);
                }
            }
        }
    }
}


void Foam::inducedDipole::findPairs()
{
    const label n = x_.size();
    pairs_.clear();

    // Without the charges' fields a pair of two unpolarisable particles
    // has no term
    markPolarisable();
    const DynamicList<bool>& polar = polar_;
    auto hasTerms = [&](const label i, const label j)
    {
        return chargeFields_ || polar[i] || polar[j];
    };

    auto weight = [&](const label i, const label j)
    {
        return
            weightedPairs_.size()
         && weightedPairs_.found(labelPair(min(i, j), max(i, j)))
          ? pairWeight_ : scalar(1);
    };

    // Minimum image in the periodic directions
    auto minImage = [&](vector r)
    {
        for (direction d = 0; d < 3; ++d)
        {
            if (period_[d] > 0)
            {
                r[d] -= period_[d]*std::round(r[d]/period_[d]);
            }
        }
        return r;
    };

    if (!(rNear_ > 0))
    {
        for (label i = 0; i < n; ++i)
        {
            for (label j = i + 1; j < n; ++j)
            {
                if (hasTerms(i, j))
                {
                    pairs_.append
                    (
                        pair{i, j, minImage(x_[i] - x_[j]), weight(i, j)}
                    );
                }
            }
        }
    }
    else
    {
        // Sources: the particles and their periodic images
        setSources();
        const DynamicList<label>& ofSource = ofSource_;
        forPairsWithinCutoff
        (
            x_, xS_, rNear_, 0,
            [&](const label t, const label s, const vector& r, const scalar)
            {
                const label j = ofSource[s];
                if (t < j && hasTerms(t, j))
                {
                    pairs_.append(pair{t, j, r, weight(t, j)});
                }
            }
        );
    }

    for (const pair& ij : pairs_)
    {
        if (magSqr(ij.r) == 0)
        {
            FatalErrorInFunction
                << "Particles " << ij.i << " and " << ij.j
                << " are at the same point " << x_[ij.i]
                << exit(FatalError);
        }
    }
}


void Foam::inducedDipole::markPolarisable()
{
    polar_.resize(alpha_.size());
    forAll(alpha_, i)
    {
        polar_[i] = cmptMax(cmptMag(alpha_[i])) > 0;
    }
}


void Foam::inducedDipole::setUpOperator()
{
    // Polarisable particles, the preconditioner's inverses and the dipole
    // tensors T = k (3 r r/r^2 - I)/r^3 of the pairs of two polarisable
    // particles
    const label n = x_.size();
    const scalar k = 1/(4*pi*pairwiseCoulomb::vacuumPermittivity*kappa0_);
    markPolarisable();
    const DynamicList<bool>& polar = polar_;
    DynamicList<tensor>& alphaInv = alphaInv_;
    alphaInv.resize(n);
    alphaInv = Zero;
    forAll(alpha_, i)
    {
        if (polar[i])
        {
            alphaInv[i] = inv(alpha_[i]);
        }
    }

    DynamicList<label>& tPairs = tPairs_;
    DynamicList<symmTensor>& T = T_;
    tPairs.clear();
    T.clear();
    forAll(pairs_, pairi)
    {
        const pair& ij = pairs_[pairi];
        if (polar[ij.i] && polar[ij.j])
        {
            const scalar r2 = magSqr(ij.r);
            const scalar ir3 = 1/(r2*Foam::sqrt(r2));
            tPairs.append(pairi);
            T.append(k*ir3*(3*sqr(ij.r)/r2 - symmTensor::I));
        }
    }
}


void Foam::inducedDipole::applyOperator
(
    List<vector>& v,
    List<vector>& Av
) const
{
    // (alpha^-1 - T) v, the copies' entries of v from their owners first
    if (owned_.size() == v.size())
    {
        updateCopies_(v);
    }
    forAll(v, i)
    {
        Av[i] = polar_[i] ? (alphaInv_[i] & v[i]) : vector::zero;
    }
    forAll(tPairs_, t)
    {
        const pair& ij = pairs_[tPairs_[t]];
        Av[ij.i] -= T_[t] & v[ij.j];
        Av[ij.j] -= T_[t] & v[ij.i];
    }
}


Foam::scalar Foam::inducedDipole::dot
(
    const UList<vector>& a,
    const UList<vector>& b
) const
{
    // Over the owned particles, summed over the processors if distributed
    const bool distributed = owned_.size() == a.size();
    scalar s = 0;
    forAll(a, i)
    {
        if (!distributed || owned_[i])
        {
            s += a[i] & b[i];
        }
    }
    return distributed ? sumOverProcessors_(s) : s;
}


void Foam::inducedDipole::solveDipoles()
{
    const List<vector>& Ec = Ec_;
    // Hand-written preconditioned CG rather than an Eigen sparse solver:
    // the operator is applied from the pair list with 3x3 blocks and no
    // assembly (the pairs change every step), and the block-diagonal
    // preconditioner alpha is exact for isolated particles
    const label n = x_.size();
    setUpOperator();
    const bool distributed = owned_.size() == n;

    DynamicList<vector>& b = b_;
    b.resize(n);
    forAll(b, i)
    {
        b[i] = polar_[i] ? Ec[i] : vector::zero;
    }

    // Start: the last dipoles, or each particle's own response alpha Ec
    p_.setSize(n);
    if (pGuess_.size() == n)
    {
        forAll(p_, i)
        {
            p_[i] = polar_[i] ? pGuess_[i] : vector::zero;
        }
    }
    else
    {
        forAll(p_, i)
        {
            p_[i] = alpha_[i] & b[i];
        }
    }

    DynamicList<vector>& r = r_;
    DynamicList<vector>& z = z_;
    DynamicList<vector>& d = d_;
    DynamicList<vector>& Ad = Ad_;
    r.resize(n);
    z.resize(n);
    d.resize(n);
    Ad.resize(n);
    applyOperator(p_, Ad);
    forAll(r, i)
    {
        r[i] = b[i] - Ad[i];
        z[i] = alpha_[i] & r[i];
    }
    d = z;

    // Converged when the preconditioned residual norm r.alpha.r is below
    // tolerance^2 of the right-hand side's b.alpha.b (scale free)
    DynamicList<vector>& ab = ab_;
    ab.resize(n);
    forAll(ab, i)
    {
        ab[i] = alpha_[i] & b[i];
    }
    const scalar bNorm = dot(b, ab);
    scalar rz = dot(r, z);
    iterations_ = 0;
    residual_ = bNorm > 0 ? Foam::sqrt(max(rz, scalar(0))/bNorm) : 0;

    while (residual_ > tolerance_ && iterations_ < maxIter_)
    {
        applyOperator(d, Ad);
        const scalar dAd = dot(d, Ad);
        if (!(dAd > 0))
        {
            FatalErrorInFunction
                << "The induced-dipole system is not positive definite"
                << " (d.A.d = " << dAd << "): point dipoles this close"
                << " polarise without bound (polarisation catastrophe);"
                << " a surface-resolved near field is needed here"
                << exit(FatalError);
        }
        const scalar a = rz/dAd;
        forAll(p_, i)
        {
            p_[i] += a*d[i];
            r[i] -= a*Ad[i];
            z[i] = alpha_[i] & r[i];
        }
        const scalar rzNew = dot(r, z);
        forAll(d, i)
        {
            d[i] = z[i] + (rzNew/rz)*d[i];
        }
        rz = rzNew;
        ++iterations_;
        residual_ = Foam::sqrt(max(rz, scalar(0))/bNorm);
    }

    if (distributed)
    {
        // The copies' dipoles from their owners (the outputs' pair terms)
        updateCopies_(p_);
    }

    if (residual_ > tolerance_)
    {
        WarningInFunction
            << "induced dipoles not converged in " << maxIter_
            << " iterations (residual " << residual_ << ")" << endl;
    }
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
    rNear_(-1),
    period_(Zero),
    chargeFields_(true),
    Eext_(Zero),
    pairWeight_(1),
    energy_(0),
    externalEnergy_(0),
    iterations_(0),
    residual_(0)
{
    if (!(kappa0 > 0) || !(tolerance > 0) || maxIter < 1)
    {
        FatalErrorInFunction
            << "kappa0 = " << kappa0 << " (> 0), tolerance = " << tolerance
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
    if (cmptMin(semiAxes) <= 0 || !(kappaP >= kappa0_))
    {
        FatalErrorInFunction
            << "semiAxes " << semiAxes << " must be > 0 and kappaP "
            << kappaP << " >= kappa0 " << kappa0_ << exit(FatalError);
    }
    x_.append(centre);
    q_.append(q);
    alpha_.append(polarisability(semiAxes, R, kappaP, kappa0_));
    E0_.append(Zero);
    return x_.size() - 1;
}


void Foam::inducedDipole::setParticles
(
    const UList<point>& x,
    const UList<scalar>& q,
    const UList<tensor>& alpha,
    const UList<vector>& E0
)
{
    if (q.size() != x.size() || alpha.size() != x.size() || E0.size() != x.size())
    {
        FatalErrorInFunction
            << "Sizes differ: " << x.size() << " centres, " << q.size()
            << " charges, " << alpha.size() << " polarisabilities, "
            << E0.size() << " fields" << abort(FatalError);
    }
    x_ = x;
    q_ = q;
    alpha_ = alpha;
    E0_ = E0;
}


void Foam::inducedDipole::setMediumPermittivity(const scalar kappa0)
{
    if (!(kappa0 > 0))
    {
        FatalErrorInFunction
            << "kappa0 = " << kappa0 << " out of range (> 0)"
            << exit(FatalError);
    }
    kappa0_ = kappa0;
}


void Foam::inducedDipole::setPairWeights
(
    const UList<labelPair>& pairs,
    const scalar w
)
{
    weightedPairs_.clear();
    for (const labelPair& ij : pairs)
    {
        weightedPairs_.insert
        (
            labelPair(min(ij.first(), ij.second()), max(ij.first(), ij.second()))
        );
    }
    pairWeight_ = w;
}


void Foam::inducedDipole::setDistribution
(
    const boolList& owned,
    const std::function<void(UList<vector>&)>& updateCopies,
    const std::function<scalar(scalar)>& sumOverProcessors
)
{
    owned_ = owned;
    updateCopies_ = updateCopies;
    sumOverProcessors_ = sumOverProcessors;
}


Foam::scalar Foam::inducedDipole::setChargeFields(const scalar k)
{
    const label n = x_.size();

    // Field of the charges and the external field (Ec, the right-hand
    // side of Eqs. 46-47), and the charges' pair energy
    DynamicList<vector>& Ec = Ec_;
    Ec.resize(n);
    forAll(Ec, i)
    {
        Ec[i] = E0_[i] + Eext_;
    }
    // Distributed: a pair's energy is shared by its owned members' sides
    const bool distributed = owned_.size() == n;
    auto ownedShare = [&](const label i, const label j)
    {
        return distributed ? 0.5*(owned_[i] + owned_[j]) : scalar(1);
    };
    scalar Uqq = 0;
    if (chargeFields_)
    {
        for (const pair& ij : pairs_)
        {
            const scalar r2 = magSqr(ij.r);
            const scalar ir = 1/Foam::sqrt(r2);
            const vector kr = (k*ir*ir*ir)*ij.r;
            Ec[ij.i] += q_[ij.j]*kr;
            Ec[ij.j] -= q_[ij.i]*kr;
            Uqq += ownedShare(ij.i, ij.j)*k*q_[ij.i]*q_[ij.j]*ir;
        }
    }
    return Uqq;
}


void Foam::inducedDipole::addPairForces(const scalar k, const scalar c)
{
    // Total fields, forces (Eq. 45) and torques, pair by pair: for the
    // pair (i, j), r = x_i - x_j, the field of j at i and its gradient
    // G_ab = d_a E_b (odd or even in r, which gives the other side)
    const label n = x_.size();
    E_ = Ec_;
    dF_.setSize(n);
    dF_ = Zero;
    M_.setSize(n);
    M_ = Zero;
    for (const pair& ij : pairs_)
    {
        const label i = ij.i, j = ij.j;
        const vector& r = ij.r;
        const scalar r2 = magSqr(r);
        const scalar ir = 1/Foam::sqrt(r2);
        const scalar ir3 = ir*ir*ir, ir5 = ir3*ir*ir, ir7 = ir5*ir*ir;
        const symmTensor rr = sqr(r);

        // Charges: E_q(j at i) = k q_j r/r^3 (odd), G_q even
        const vector eq = (k*ir3)*r;
        const symmTensor gq = k*(ir3*symmTensor::I - 3*ir5*rr);

        // Dipoles: E_p(j at i) even in r, G_p odd
        auto Ep = [&](const vector& p)
        {
            return k*(3*(p & r)*ir5*r - ir3*p);
        };
        auto Gp = [&](const vector& p)
        {
            const scalar pr = p & r;
            return k*
            (
                3*ir5*(twoSymm(p*r) + pr*symmTensor::I)
              - 15*pr*ir7*rr
            );
        };
        const vector& pI = p_[i];
        const vector& pJ = p_[j];
        const vector Epj = Ep(pJ);     // at i
        const vector Epi = Ep(pI);     // at j
        const symmTensor Gpj = Gp(pJ);     // at i
        const symmTensor Gpi = -Gp(pI);    // at j (odd)

        E_[i] += Epj;
        E_[j] += Epi;

        const scalar w = ij.w;
        dF_[i] += w*
        (
            c*q_[i]*q_[j]*eq + q_[i]*Epj + (pI & (q_[j]*gq + Gpj))
        );
        dF_[j] += w*
        (
           -c*q_[j]*q_[i]*eq + q_[j]*Epi + (pJ & (q_[i]*gq + Gpi))
        );

        // Torques of the pair's fields; the charges' fields in E0 (far
        // field) re-weighted when they are not counted here
        const scalar wq = w - 1 + c;
        M_[i] += pI ^ (w*Epj + wq*q_[j]*eq);
        M_[j] += pJ ^ (w*Epi - wq*q_[i]*eq);
    }
}


Foam::label Foam::inducedDipole::solve()
{
    const label n = x_.size();
    const scalar k = 1/(4*pi*pairwiseCoulomb::vacuumPermittivity*kappa0_);
    const scalar c = chargeFields_ ? 1 : 0;

    findPairs();
    const scalar Uqq = setChargeFields(k);
    solveDipoles();
    addPairForces(k, c);

    const bool distributed = owned_.size() == n;
    F_.setSize(n);
    energy_ = c*Uqq;
    externalEnergy_ = 0;
    forAll(F_, i)
    {
        const vector E0 = E0_[i] + Eext_;
        F_[i] = q_[i]*E0 + dF_[i];
        M_[i] += p_[i] ^ E0;
        if (!distributed || owned_[i])
        {
            energy_ -= 0.5*(p_[i] & (Ec_[i] - E0));
            externalEnergy_ -= 0.5*(p_[i] & E0);
        }
    }
    if (distributed)
    {
        energy_ = sumOverProcessors_(energy_);
        externalEnergy_ = sumOverProcessors_(externalEnergy_);
    }

    return iterations_;
}


// ************************************************************************* //
