/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ewaldSum.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <vector>

using Foam::constant::mathematical::pi;
using Foam::constant::mathematical::twoPi;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::ewaldSum::ewaldSum
(
    const vector& L,
    const scalar epsilonR,
    const scalar tolerance
)
:
    periodicElectrostatics(L, epsilonR),
    tolerance_(tolerance)
{
    if (!(tolerance > 0) || !(tolerance <= 1e-3))
    {
        FatalErrorInFunction
            << "Ewald tolerance = " << tolerance << " is out of range"
            << " (0, 1e-3]" << exit(FatalError);
    }
}


Foam::ewaldSum::ewaldSum(const dictionary& dict)
:
    ewaldSum
    (
        readBox(dict),
        readEpsilonR(dict),
        readScalar(dict, "tolerance", 1e-10, 0, 1e-3)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::ewaldSum::parameters Foam::ewaldSum::choose
(
    const label N,
    const label M
) const
{
    // a rc = s and kmax = 2 a s make erfc(a rc) ~ exp(-s^2) and the
    // Gaussian factor exp(-kmax^2/(4 a^2)) = exp(-s^2) below the tolerance;
    // the 0.3 margin covers the 2 a r/sqrt(pi) prefactor of the real-space
    // force term
    const scalar s = Foam::sqrt(-Foam::log(tolerance_)) + 0.3;
    const scalar Lmin = cmptMin(L_);

    parameters best;
    scalar bestCost = GREAT;

    // Real space visits every pair and its images within rc (no cell list:
    // the reference favours simplicity), so rc >= Lmin/2 costs nothing more
    // in pair visits; pick the rc balancing both sums. A real-space pair
    // (erfc, exp) costs about 10 reciprocal-space complex products.
    for (const scalar c : {0.5, 0.625, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5})
    {
        parameters p;
        p.rCut = c*Lmin;
        p.alpha = s/p.rCut;
        p.kCut = 2*p.alpha*s;
        scalar nImages = 1, nk = 1;
        for (direction d = 0; d < 3; ++d)
        {
            p.nImage[d] = label(std::floor(p.rCut/L_[d] + 0.5));
            p.nk[d] = label(std::ceil(p.kCut*L_[d]/twoPi));
            nImages *= 2*p.nImage[d] + 1;
            nk *= p.nk[d];
        }
        const scalar nkSphere = (4*pi/3)*nk/2;
        const scalar cost =
            10*scalar(M)*scalar(N)*nImages + scalar(N + M)*nkSphere;
        if (cost < bestCost)
        {
            bestCost = cost;
            best = p;
        }
    }
    return best;
}


void Foam::ewaldSum::realSpace
(
    const parameters& p,
    const UList<point>& x,
    const UList<scalar>& q,
    const labelUList& targets,
    UList<vector>& f,
    scalar* energy
) const
{
    const label N = x.size();
    const bool all = targets.empty();
    const label M = all ? N : targets.size();
    const scalar a = p.alpha;
    const scalar rc2 = sqr(p.rCut);
    const scalar twoAOverSqrtPi = 2*a/Foam::sqrt(pi);
    const label* nI = p.nImage;

    scalar e = 0;

    // Sum over the images n of one pair with minimum-image separation d;
    // `self` skips n = 0 (a particle with its own images)
    auto pairSum = [&](const vector& d, const bool self, vector& fij)
    {
        scalar eij = 0;
        for (label n0 = -nI[0]; n0 <= nI[0]; ++n0)
        {
            for (label n1 = -nI[1]; n1 <= nI[1]; ++n1)
            {
                for (label n2 = -nI[2]; n2 <= nI[2]; ++n2)
                {
                    if (self && n0 == 0 && n1 == 0 && n2 == 0) continue;
                    const vector r
                    (
                        d.x() + n0*L_.x(),
                        d.y() + n1*L_.y(),
                        d.z() + n2*L_.z()
                    );
                    const scalar r2 = magSqr(r);
                    if (r2 >= rc2) continue;
                    const scalar rm = Foam::sqrt(r2);
                    const scalar erfcTerm = std::erfc(a*rm)/rm;
                    fij +=
                        ((erfcTerm + twoAOverSqrtPi*Foam::exp(-a*a*r2))/r2)*r;
                    eij += erfcTerm;
                }
            }
        }
        return eij;
    };

    if (all)
    {
        for (label i = 0; i < N; ++i)
        {
            vector fi(Zero);
            for (label j = i + 1; j < N; ++j)
            {
                const vector d = minImage(x[i] - x[j]);
                if (magSqr(d) == 0)
                {
                    FatalErrorInFunction
                        << "Charges " << i << " and " << j << " coincide at "
                        << x[i] << " (modulo the box)" << exit(FatalError);
                }
                vector fij(Zero);
                const scalar eij = pairSum(d, false, fij);
                fi += q[j]*fij;
                f[j] -= q[i]*fij;
                e += q[i]*q[j]*eij;
            }
            f[i] += fi;
            if (energy)
            {
                // Own images: forces cancel in +-n pairs, energy does not
                vector fSelf(Zero);
                e += 0.5*sqr(q[i])*pairSum(Zero, true, fSelf);
            }
        }
        forAll(f, i)
        {
            f[i] *= k_*q[i];
        }
    }
    else
    {
        for (label m = 0; m < M; ++m)
        {
            const label i = targets[m];
            vector fi(Zero);
            for (label j = 0; j < N; ++j)
            {
                if (j == i) continue;
                vector fij(Zero);
                pairSum(minImage(x[i] - x[j]), false, fij);
                fi += q[j]*fij;
            }
            f[m] += (k_*q[i])*fi;
        }
    }

    if (energy)
    {
        *energy += k_*e;
    }
}


namespace
{

using Foam::scalar;
using Foam::label;

// A wave vector of the half space (k and -k give complex conjugate terms):
// its indices, k and the coefficient (4 pi/V) exp(-k^2/(4 a^2))/k^2
struct kVec { label m0, m1, m2; Foam::vector k; scalar coef; };

// The half space of wave vectors within kCut of the box L
std::vector<kVec> halfSpace
(
    const Foam::vector& L,
    const scalar alpha,
    const scalar kCut,
    const label n0,
    const label n1,
    const label n2
)
{
    const scalar V = L.x()*L.y()*L.z();
    const scalar kc2 = Foam::sqr(kCut);
    const Foam::vector dk(twoPi/L.x(), twoPi/L.y(), twoPi/L.z());
    std::vector<kVec> ks;
    for (label m0 = 0; m0 <= n0; ++m0)
    {
        for (label m1 = -n1; m1 <= n1; ++m1)
        {
            for (label m2 = -n2; m2 <= n2; ++m2)
            {
                if (m0 == 0 && (m1 < 0 || (m1 == 0 && m2 <= 0))) continue;
                const Foam::vector kv(m0*dk.x(), m1*dk.y(), m2*dk.z());
                const scalar k2 = Foam::magSqr(kv);
                if (k2 > kc2) continue;
                ks.push_back
                ({
                    m0, m1, m2, kv,
                    (4*pi/V)*Foam::exp(-k2/(4*alpha*alpha))/k2
                });
            }
        }
    }
    return ks;
}


// exp(i k.x) by per-direction tables (m = -n..n; m = 0..n0 in the first
// direction), for a chunk of particles at a time to bound the memory
struct phaseTables
{
    const label chunk;
    const label n[3];
    const Foam::vector dk;
    std::vector<scalar> c[3], s[3];

    phaseTables
    (
        const label chunkSize,
        const label n0,
        const label n1,
        const label n2,
        const Foam::vector& L
    )
    :
        chunk(chunkSize),
        n{n0, n1, n2},
        dk(twoPi/L.x(), twoPi/L.y(), twoPi/L.z())
    {
        c[0].resize((n0 + 1)*chunk);
        s[0].resize((n0 + 1)*chunk);
        c[1].resize((2*n1 + 1)*chunk);
        s[1].resize((2*n1 + 1)*chunk);
        c[2].resize((2*n2 + 1)*chunk);
        s[2].resize((2*n2 + 1)*chunk);
    }

    // The tables of the nj points x[idx[j0 + jj]] (idx null: x[j0 + jj])
    void fill
    (
        const Foam::UList<Foam::point>& x,
        const label* idx,
        const label j0,
        const label nj
    )
    {
        for (label jj = 0; jj < nj; ++jj)
        {
            const label j = idx ? idx[j0 + jj] : j0 + jj;
            const Foam::point& xj = x[j];
            const scalar ph[3] =
                {dk.x()*xj.x(), dk.y()*xj.y(), dk.z()*xj.z()};
            for (Foam::direction d = 0; d < 3; ++d)
            {
                const label off = (d == 0) ? 0 : n[d];
                const scalar cd = Foam::cos(ph[d]), sd = Foam::sin(ph[d]);
                scalar cr = 1, sr = 0;
                for (label m = 0; m <= n[d]; ++m)
                {
                    // Recurrence drifts ~m eps: fine for m <= ~100
                    c[d][(off + m)*chunk + jj] = cr;
                    s[d][(off + m)*chunk + jj] = sr;
                    if (d > 0)
                    {
                        c[d][(off - m)*chunk + jj] = cr;
                        s[d][(off - m)*chunk + jj] = -sr;
                    }
                    const scalar t = cr*cd - sr*sd;
                    sr = sr*cd + cr*sd;
                    cr = t;
                }
            }
        }
    }
};

} // End anonymous namespace


void Foam::ewaldSum::kSpace
(
    const parameters& p,
    const UList<point>& x,
    const UList<scalar>& q,
    const labelUList& targets,
    UList<vector>& f,
    scalar* energy
) const
{
    const label N = x.size();
    const bool all = targets.empty();
    const label M = all ? N : targets.size();
    const label n1 = p.nk[1], n2 = p.nk[2];
    const std::vector<kVec> ks
    (
        halfSpace(L_, p.alpha, p.kCut, p.nk[0], n1, n2)
    );
    const label nK = ks.size();

    // Complex products written out by hand (std::complex multiplication
    // checks for inf/nan and is slow)
    const label chunk = 2048;
    phaseTables tab(chunk, p.nk[0], n1, n2, L_);
    const std::vector<scalar>& c0 = tab.c[0];
    const std::vector<scalar>& s0 = tab.s[0];
    const std::vector<scalar>& c1 = tab.c[1];
    const std::vector<scalar>& s1 = tab.s[1];
    const std::vector<scalar>& c2 = tab.c[2];
    const std::vector<scalar>& s2 = tab.s[2];
    const auto tables = [&](const label* idx, const label j0, const label nj)
    {
        tab.fill(x, idx, j0, nj);
    };

    // Structure factors S(k) = sum_j q_j exp(i k.x_j)
    std::vector<scalar> Sre(nK, 0), Sim(nK, 0);
    for (label j0 = 0; j0 < N; j0 += chunk)
    {
        const label nj = std::min(chunk, N - j0);
        tables(nullptr, j0, nj);
        for (label kk = 0; kk < nK; ++kk)
        {
            const kVec& kv = ks[kk];
            const scalar* a0 = &c0[kv.m0*chunk];
            const scalar* b0 = &s0[kv.m0*chunk];
            const scalar* a1 = &c1[(n1 + kv.m1)*chunk];
            const scalar* b1 = &s1[(n1 + kv.m1)*chunk];
            const scalar* a2 = &c2[(n2 + kv.m2)*chunk];
            const scalar* b2 = &s2[(n2 + kv.m2)*chunk];
            scalar re = 0, im = 0;
            for (label jj = 0; jj < nj; ++jj)
            {
                const scalar r01 = a0[jj]*a1[jj] - b0[jj]*b1[jj];
                const scalar i01 = a0[jj]*b1[jj] + b0[jj]*a1[jj];
                const scalar qj = q[j0 + jj];
                re += qj*(r01*a2[jj] - i01*b2[jj]);
                im += qj*(r01*b2[jj] + i01*a2[jj]);
            }
            Sre[kk] += re;
            Sim[kk] += im;
        }
    }

    if (energy)
    {
        // (2 pi/V) sum over all k != 0 = twice the half space
        scalar e = 0;
        for (label kk = 0; kk < nK; ++kk)
        {
            e += 0.5*ks[kk].coef*(sqr(Sre[kk]) + sqr(Sim[kk]));
        }
        *energy += 2*k_*e;
    }

    // Fields at the targets: 2 x (half space) x coef k Im[e^{ik.x} S*]
    std::vector<scalar> Ex(chunk), Ey(chunk), Ez(chunk);
    for (label m0 = 0; m0 < M; m0 += chunk)
    {
        const label nm = std::min(chunk, M - m0);
        tables(all ? nullptr : targets.cdata(), m0, nm);
        std::fill(Ex.begin(), Ex.end(), 0);
        std::fill(Ey.begin(), Ey.end(), 0);
        std::fill(Ez.begin(), Ez.end(), 0);
        for (label kk = 0; kk < nK; ++kk)
        {
            const kVec& kv = ks[kk];
            const scalar* a0 = &c0[kv.m0*chunk];
            const scalar* b0 = &s0[kv.m0*chunk];
            const scalar* a1 = &c1[(n1 + kv.m1)*chunk];
            const scalar* b1 = &s1[(n1 + kv.m1)*chunk];
            const scalar* a2 = &c2[(n2 + kv.m2)*chunk];
            const scalar* b2 = &s2[(n2 + kv.m2)*chunk];
            const scalar sr = Sre[kk], si = Sim[kk];
            const scalar cx = 2*kv.coef*kv.k.x();
            const scalar cy = 2*kv.coef*kv.k.y();
            const scalar cz = 2*kv.coef*kv.k.z();
            for (label jj = 0; jj < nm; ++jj)
            {
                const scalar r01 = a0[jj]*a1[jj] - b0[jj]*b1[jj];
                const scalar i01 = a0[jj]*b1[jj] + b0[jj]*a1[jj];
                const scalar er = r01*a2[jj] - i01*b2[jj];
                const scalar ei = r01*b2[jj] + i01*a2[jj];
                // Im[(er + i ei)(sr - i si)] = ei sr - er si
                const scalar im = ei*sr - er*si;
                Ex[jj] += cx*im;
                Ey[jj] += cy*im;
                Ez[jj] += cz*im;
            }
        }
        for (label jj = 0; jj < nm; ++jj)
        {
            const label i = all ? m0 + jj : targets[m0 + jj];
            f[m0 + jj] += (k_*q[i])*vector(Ex[jj], Ey[jj], Ez[jj]);
        }
    }
}


void Foam::ewaldSum::compute
(
    const UList<point>& x,
    const UList<scalar>& q,
    List<vector>& f
) const
{
    checkInput(x, q);
    f.setSize(x.size());
    f = Zero;
    if (x.empty()) return;
    const parameters p = choose(x.size(), x.size());
    realSpace(p, x, q, labelUList::null(), f, nullptr);
    kSpace(p, x, q, labelUList::null(), f, nullptr);
}


void Foam::ewaldSum::forces
(
    const UList<point>& x,
    const UList<scalar>& q,
    const labelUList& targets,
    List<vector>& f
) const
{
    checkInput(x, q);
    for (const label i : targets)
    {
        if (i < 0 || i >= x.size())
        {
            FatalErrorInFunction
                << "Target index " << i << " is out of range [0, "
                << x.size() - 1 << "]" << exit(FatalError);
        }
    }
    f.setSize(targets.size());
    f = Zero;
    if (targets.empty()) return;
    const parameters p = choose(x.size(), targets.size());
    realSpace(p, x, q, targets, f, nullptr);
    kSpace(p, x, q, targets, f, nullptr);
}


Foam::scalar Foam::ewaldSum::energy
(
    const UList<point>& x,
    const UList<scalar>& q
) const
{
    checkInput(x, q);
    if (x.empty()) return 0;
    const parameters p = choose(x.size(), x.size());
    List<vector> f(x.size(), Zero);
    scalar e = 0;
    realSpace(p, x, q, labelUList::null(), f, &e);
    kSpace(p, x, q, labelUList::null(), f, &e);

    scalar Q = 0, Q2 = 0;
    for (const scalar qi : q)
    {
        Q += qi;
        Q2 += qi*qi;
    }
    const scalar V = L_.x()*L_.y()*L_.z();
    // Self energy and the neutralising background (Q != 0)
    e -= k_*(p.alpha/Foam::sqrt(pi)*Q2 + pi*Q*Q/(2*V*sqr(p.alpha)));
    return e;
}


void Foam::ewaldSum::writeInfo(Ostream& os) const
{
    periodicElectrostatics::writeInfo(os);
    os  << ", tolerance = " << tolerance_;
}


// ************************************************************************* //
