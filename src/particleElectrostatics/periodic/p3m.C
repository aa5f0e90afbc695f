/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "p3m.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "Switch.H"
#include "OStringStream.H"
#include "Pstream.H"
#include "processorHalo.H"
#include "cutoffPairs.H"
#include "checkedEntry.H"
#include "ListListOps.H"

#include <mpi.h>
#include <fftw3-mpi.h>
#include <chrono>
#include <algorithm>
#include <array>

using Foam::constant::mathematical::pi;
using Foam::constant::mathematical::twoPi;

// * * * * * * * * * * * * * * * Local functions * * * * * * * * * * * * * * //

namespace
{

using Foam::scalar;
using Foam::label;

// Coefficients of the closed-form k-space error of ik-differentiated P3M
// (Deserno & Holm 1998 II, as tabulated in LAMMPS' pppm.cpp), a[P][m]
const double acons[8][7] =
{
    {0, 0, 0, 0, 0, 0, 0},
    {2.0/3.0, 0, 0, 0, 0, 0, 0},
    {1.0/50.0, 5.0/294.0, 0, 0, 0, 0, 0},
    {1.0/588.0, 7.0/1440.0, 21.0/3872.0, 0, 0, 0, 0},
    {1.0/4320.0, 3.0/1936.0, 7601.0/2271360.0, 143.0/28800.0, 0, 0, 0},
    {
        1.0/23232.0, 7601.0/13628160.0, 143.0/69120.0,
        517231.0/106536960.0, 106640677.0/11737571328.0, 0, 0
    },
    {
        691.0/68140800.0, 13.0/57600.0, 47021.0/35512320.0,
        9694607.0/2095994880.0, 733191589.0/59609088000.0,
        326190917.0/11700633600.0, 0
    },
    {
        1.0/345600.0, 3617.0/35512320.0, 745739.0/838397952.0,
        56399353.0/12773376000.0, 25091609.0/1560084480.0,
        1755948832039.0/36229939200000.0, 4887769399.0/37838389248.0
    }
};


// w[j] = M_P(t + j), j = 0..P-1: the uncentred cardinal B-spline of order
// P (support [0, P]) by its recurrence (Essmann et al. 1995, Eq. 4.1); a
// charge at mesh coordinate u = m + t gets w[j] at mesh point m - j.
// Uncentred = centred shifted by P/2 for every particle alike: the same
// shift in assignment and interpolation leaves the forces unchanged.
inline void bspline(const label P, const scalar t, scalar* w)
{
    w[0] = 1;
    for (label j = 1; j < P; ++j) w[j] = 0;
    for (label k = 2; k <= P; ++k)
    {
        const scalar div = 1.0/(k - 1);
        for (label j = k - 1; j >= 0; --j)
        {
            const scalar a = (j < k - 1) ? w[j] : 0;
            const scalar b = (j > 0) ? w[j - 1] : 0;
            w[j] = ((t + j)*a + (k - t - j)*b)*div;
        }
    }
}


// Assignment stencil of a point x (wrapped into the box): per direction
// the mesh indices idx[d][j] and weights w[d][j], j < P (hi: points per
// metre, n: points per direction)
inline void assignmentStencil
(
    const Foam::point& x,
    const label P,
    const scalar hi[3],
    const label n[3],
    label idx[3][7],
    scalar w[3][7]
)
{
    for (Foam::direction d = 0; d < 3; ++d)
    {
        const scalar u = x[d]*hi[d];
        label m = label(std::floor(u));
        const scalar t = u - m;
        bspline(P, t, w[d]);
        for (label j = 0; j < P; ++j)
        {
            label mj = (m - j) % n[d];
            if (mj < 0) mj += n[d];
            idx[d][j] = mj;
        }
    }
}


// Smallest n >= nMin with prime factors 2, 3, 5, 7 only (fast FFTW sizes)
label fftSize(label nMin)
{
    for (label n = std::max(nMin, label(2)); ; ++n)
    {
        label m = n;
        for (const label p : {2, 3, 5, 7})
        {
            while (m % p == 0) m /= p;
        }
        if (m == 1) return n;
    }
}


// erfc(x) by Abramowitz & Stegun 7.1.26 (absolute error <= 1.5e-7), given
// expm2 = exp(-x^2): the form LAMMPS' pair coul/long uses without tables
inline scalar erfcFast(const scalar x, const scalar expm2)
{
    const scalar t = 1.0/(1.0 + 0.3275911*x);
    return t*(0.254829592 + t*(-0.284496736 + t*(1.421413741
          + t*(-1.453152027 + t*1.061405429))))*expm2;
}


// Entry fastErfc: -1 for auto, 0 or 1 for a bool (a word of OpenFOAM's
// Switch: true/false, on/off, yes/no, ...; or the label 0 or 1); anything
// else is an error naming the entry and the allowed values
int readFastErfc(const Foam::dictionary& dict)
{
    if (!dict.found("fastErfc"))
    {
        return -1;
    }
    const Foam::ITstream& is = dict.lookup("fastErfc");
    if (is.size() == 1)
    {
        const Foam::token& t = is[0];
        if (t.isWord())
        {
            if (t.wordToken() == "auto")
            {
                return -1;
            }
            const Foam::Switch sw(t.wordToken(), true);
            if (sw.valid())
            {
                return bool(sw) ? 1 : 0;
            }
        }
        else if (t.isLabel() && (t.labelToken() == 0 || t.labelToken() == 1))
        {
            return int(t.labelToken());
        }
    }
    Foam::OStringStream value;
    forAll(is, i)
    {
        value << (i ? " " : "") << is[i];
    }
    FatalIOErrorInFunction(dict)
        << "Entry 'fastErfc' = " << value.str().c_str() << " is out of"
        << " range: auto, or a bool (true/false, on/off, yes/no, 1/0)"
        << Foam::exit(Foam::FatalIOError);
    return -1;
}

// The real-space pair force over q_i q_j r,
// g(r^2) = (erfc(a r)/r + 2a/sqrt(pi) exp(-a^2 r^2))/r^2: tabulated
// between (rc/4)^2 and rc^2 (linear in r^2, relative error < 2e-6, as
// LAMMPS' coul/long tables trade accuracy for speed); analytic inside, and
// everywhere if !fast
class realSpaceForce
{
    static constexpr label nTab = 8192;
    const scalar a_, c2_, sIn_, invDs_;
    const bool fast_;
    const double* tab_;

public:

    // The table is made in table once (kept by the caller between calls)
    realSpaceForce
    (
        const scalar alpha,
        const scalar rc,
        const bool fast,
        std::vector<double>& table
    )
    :
        a_(alpha),
        c2_(2*alpha/Foam::sqrt(pi)),
        sIn_(Foam::sqr(0.25*rc)),
        invDs_(nTab/(rc*rc - sIn_)),
        fast_(fast),
        tab_(nullptr)
    {
        if (fast_ && table.size() != size_t(2*nTab))
        {
            table.resize(2*nTab);
            scalar g0 = exact(sIn_);
            for (label k = 0; k < nTab; ++k)
            {
                const scalar g1 = exact(sIn_ + (k + 1)/invDs_);
                table[2*k] = g0;
                table[2*k + 1] = g1 - g0;
                g0 = g1;
            }
        }
        tab_ = table.data();
    }

    scalar exact(const scalar r2) const
    {
        const scalar r = Foam::sqrt(r2);
        const scalar ar = a_*r;
        const scalar expm2 = Foam::exp(-ar*ar);
        const scalar erfcv = fast_ ? erfcFast(ar, expm2) : std::erfc(ar);
        return (erfcv/r + c2_*expm2)/r2;
    }

    scalar operator()(const scalar r2) const
    {
        if (fast_ && r2 >= sIn_)
        {
            const scalar u = (r2 - sIn_)*invDs_;
            const label k = std::min(label(u), nTab - 1);
            return tab_[2*k] + (u - k)*tab_[2*k + 1];
        }
        return exact(r2);
    }
};


// Charges sorted by cell of a periodic cell list (counting sort), as
// arrays of their coordinates, charges and whether kept (not a halo's)
struct cellSortedCharges
{
    label nc[3];
    std::vector<label> start, order, kept;
    std::vector<scalar> xs, ys, zs, qs;

    cellSortedCharges
    (
        const Foam::UList<Foam::point>& xw,
        const Foam::UList<scalar>& q,
        const label nKept,
        const Foam::vector& L,
        const label n[3]
    )
    {
        const label N = xw.size();
        for (Foam::direction d = 0; d < 3; ++d) nc[d] = n[d];
        std::vector<label> cellOf(N);
        for (label i = 0; i < N; ++i)
        {
            label c[3];
            for (Foam::direction d = 0; d < 3; ++d)
            {
                c[d] = std::min(nc[d] - 1, label(xw[i][d]*nc[d]/L[d]));
            }
            cellOf[i] = c[0] + nc[0]*(c[1] + nc[1]*c[2]);
        }
        Foam::sortByBin(cellOf, nc[0]*nc[1]*nc[2], start, order);
        xs.resize(N);
        ys.resize(N);
        zs.resize(N);
        qs.resize(N);
        kept.resize(N);
        for (label s = 0; s < N; ++s)
        {
            const label i = order[s];
            xs[s] = xw[i].x();
            ys[s] = xw[i].y();
            zs[s] = xw[i].z();
            qs[s] = q[i];
            kept[s] = i < nKept;
        }
    }
};


// Half stencil of a cell list (each neighbour pair of cells once) within
// reach cells
std::vector<std::array<label, 3>> halfStencil(const label reach)
{
    std::vector<std::array<label, 3>> stencil;
    for (label dz = -reach; dz <= reach; ++dz)
    {
        for (label dy = -reach; dy <= reach; ++dy)
        {
            for (label dx = -reach; dx <= reach; ++dx)
            {
                if (dz > 0 || (dz == 0 && (dy > 0 || (dy == 0 && dx > 0))))
                {
                    stencil.push_back({dx, dy, dz});
                }
            }
        }
    }
    return stencil;
}


// The pair forces within rc2 of the sorted charges c, by cells of the
// periodic box L and the stencil of reach cells, added to (fx, fy, fz) in
// sorted order. Candidates within rc are first compacted without branches
// (the accept test is unpredictable: about 27 % pass), then their forces
// computed in a second, predictable loop
template<class Force>
void cellPairForces
(
    const cellSortedCharges& c,
    const Foam::vector& L,
    const label reach,
    const scalar rc2,
    const Force& pairForce,
    std::vector<scalar>& fx,
    std::vector<scalar>& fy,
    std::vector<scalar>& fz
)
{
    const label* nc = c.nc;
    const std::vector<label>& start = c.start;
    const std::vector<label>& kept = c.kept;
    const std::vector<scalar>& xs = c.xs;
    const std::vector<scalar>& ys = c.ys;
    const std::vector<scalar>& zs = c.zs;
    const std::vector<scalar>& qs = c.qs;
    const label nCells = nc[0]*nc[1]*nc[2];
    const std::vector<std::array<label, 3>> stencil(halfStencil(reach));
    label maxCell = 0;
    for (label cl = 0; cl < nCells; ++cl)
    {
        maxCell = std::max(maxCell, start[cl + 1] - start[cl]);
    }
    const label nSt = stencil.size();
    const label cap = maxCell*(nSt + 1) + 1;
    std::vector<label> bt(cap);
    std::vector<scalar> bx(cap), by(cap), bz(cap), br(cap);
    std::vector<label> nb0(nSt), nb1(nSt);
    std::vector<scalar> shx(nSt), shy(nSt), shz(nSt);

    for (label cz = 0; cz < nc[2]; ++cz)
    for (label cy = 0; cy < nc[1]; ++cy)
    for (label cx = 0; cx < nc[0]; ++cx)
    {
        const label cl = cx + nc[0]*(cy + nc[1]*cz);
        const label s0 = start[cl], s1 = start[cl + 1];
        if (s0 == s1) continue;

        // Neighbour cells with their periodic shifts
        for (label k = 0; k < nSt; ++k)
        {
            const auto& o = stencil[k];
            label cn[3] = {cx + o[0], cy + o[1], cz + o[2]};
            scalar sh[3] = {0, 0, 0};
            for (Foam::direction d = 0; d < 3; ++d)
            {
                if (cn[d] < 0) { cn[d] += nc[d]; sh[d] = -L[d]; }
                else if (cn[d] >= nc[d]) { cn[d] -= nc[d]; sh[d] = L[d]; }
            }
            const label cc = cn[0] + nc[0]*(cn[1] + nc[1]*cn[2]);
            nb0[k] = start[cc];
            nb1[k] = start[cc + 1];
            shx[k] = sh[0];
            shy[k] = sh[1];
            shz[k] = sh[2];
        }

        for (label s = s0; s < s1; ++s)
        {
            const scalar xi = xs[s], yi = ys[s], zi = zs[s], qi = qs[s];
            const label keptI = kept[s];
            label m = 0;
            for (label t = s + 1; t < s1; ++t)
            {
                const scalar dx = xi - xs[t], dy = yi - ys[t],
                    dz = zi - zs[t];
                const scalar r2 = dx*dx + dy*dy + dz*dz;
                bt[m] = t; bx[m] = dx; by[m] = dy; bz[m] = dz; br[m] = r2;
                m += (r2 < rc2) & (keptI | kept[t]);
            }
            for (label k = 0; k < nSt; ++k)
            {
                const scalar xk = xi - shx[k], yk = yi - shy[k],
                    zk = zi - shz[k];
                for (label t = nb0[k]; t < nb1[k]; ++t)
                {
                    const scalar dx = xk - xs[t], dy = yk - ys[t],
                        dz = zk - zs[t];
                    const scalar r2 = dx*dx + dy*dy + dz*dz;
                    bt[m] = t; bx[m] = dx; by[m] = dy; bz[m] = dz;
                    br[m] = r2;
                    m += (r2 < rc2) & (keptI | kept[t]);
                }
            }

            scalar fxi = 0, fyi = 0, fzi = 0;
            for (label j = 0; j < m; ++j)
            {
                const scalar r2 = br[j];
                if (r2 == 0)
                {
                    FatalErrorInFunction
                        << "Charges " << c.order[s] << " and " << c.order[bt[j]]
                        << " coincide (modulo the box)"
                        << Foam::exit(Foam::FatalError);
                }
                const label t = bt[j];
                const scalar g = qi*qs[t]*pairForce(r2);
                const scalar gx = g*bx[j], gy = g*by[j], gz = g*bz[j];
                fxi += gx; fyi += gy; fzi += gz;
                fx[t] -= gx; fy[t] -= gy; fz[t] -= gz;
            }
            fx[s] += fxi; fy[s] += fyi; fz[s] += fzi;
        }
    }
}


// Visits the pairs within rc2 of the sorted charges c, by cells of the
// periodic box L and the stencil of reach cells: v.visit(s, m, t, dx, dy,
// dz, r2) with the m partners t of s (indices in sorted order, each pair
// once). The potentials' traversal: the forces keep cellPairForces, the
// same traversal written out (a visitor there measured 13 % slower real
// space, median of 5 pairs at 5e4 charges). Candidates within rc are
// compacted first, as there
template<class Visitor>
void cellPairs
(
    const cellSortedCharges& c,
    const Foam::vector& L,
    const label reach,
    const scalar rc2,
    Visitor& v
)
{
    const label* nc = c.nc;
    const std::vector<label>& start = c.start;
    const std::vector<label>& kept = c.kept;
    const std::vector<scalar>& xs = c.xs;
    const std::vector<scalar>& ys = c.ys;
    const std::vector<scalar>& zs = c.zs;
    const label nCells = nc[0]*nc[1]*nc[2];
    const std::vector<std::array<label, 3>> stencil(halfStencil(reach));
    label maxCell = 0;
    for (label cl = 0; cl < nCells; ++cl)
    {
        maxCell = std::max(maxCell, start[cl + 1] - start[cl]);
    }
    const label nSt = stencil.size();
    const label cap = maxCell*(nSt + 1) + 1;
    std::vector<label> bt(cap);
    std::vector<scalar> bx(cap), by(cap), bz(cap), br(cap);
    std::vector<label> nb0(nSt), nb1(nSt);
    std::vector<scalar> shx(nSt), shy(nSt), shz(nSt);

    for (label cz = 0; cz < nc[2]; ++cz)
    for (label cy = 0; cy < nc[1]; ++cy)
    for (label cx = 0; cx < nc[0]; ++cx)
    {
        const label cl = cx + nc[0]*(cy + nc[1]*cz);
        const label s0 = start[cl], s1 = start[cl + 1];
        if (s0 == s1) continue;

        // Neighbour cells with their periodic shifts
        for (label k = 0; k < nSt; ++k)
        {
            const auto& o = stencil[k];
            label cn[3] = {cx + o[0], cy + o[1], cz + o[2]};
            scalar sh[3] = {0, 0, 0};
            for (Foam::direction d = 0; d < 3; ++d)
            {
                if (cn[d] < 0) { cn[d] += nc[d]; sh[d] = -L[d]; }
                else if (cn[d] >= nc[d]) { cn[d] -= nc[d]; sh[d] = L[d]; }
            }
            const label cc = cn[0] + nc[0]*(cn[1] + nc[1]*cn[2]);
            nb0[k] = start[cc];
            nb1[k] = start[cc + 1];
            shx[k] = sh[0];
            shy[k] = sh[1];
            shz[k] = sh[2];
        }

        for (label s = s0; s < s1; ++s)
        {
            const scalar xi = xs[s], yi = ys[s], zi = zs[s];
            const label keptI = kept[s];
            label m = 0;
            for (label t = s + 1; t < s1; ++t)
            {
                const scalar dx = xi - xs[t], dy = yi - ys[t],
                    dz = zi - zs[t];
                const scalar r2 = dx*dx + dy*dy + dz*dz;
                bt[m] = t; bx[m] = dx; by[m] = dy; bz[m] = dz; br[m] = r2;
                m += (r2 < rc2) & (keptI | kept[t]);
            }
            for (label k = 0; k < nSt; ++k)
            {
                const scalar xk = xi - shx[k], yk = yi - shy[k],
                    zk = zi - shz[k];
                for (label t = nb0[k]; t < nb1[k]; ++t)
                {
                    const scalar dx = xk - xs[t], dy = yk - ys[t],
                        dz = zk - zs[t];
                    const scalar r2 = dx*dx + dy*dy + dz*dz;
                    bt[m] = t; bx[m] = dx; by[m] = dy; bz[m] = dz;
                    br[m] = r2;
                    m += (r2 < rc2) & (keptI | kept[t]);
                }
            }

            for (label j = 0; j < m; ++j)
            {
                if (br[j] == 0)
                {
                    FatalErrorInFunction
                        << "Charges " << c.order[s] << " and " << c.order[bt[j]]
                        << " coincide (modulo the box)"
                        << Foam::exit(Foam::FatalError);
                }
            }
            v.visit(s, m, bt.data(), bx.data(), by.data(), bz.data(), br.data());
        }
    }
}


// Pair visitor of the real-space potentials q_j erfc(a r)/r (std::erfc:
// the potential is a diagnostic, not the hot path)
class realSpacePotentialSum
{
    const scalar* q_;
    const scalar a_;
    std::vector<scalar> phi_;

public:

    explicit realSpacePotentialSum(const scalar alpha)
    :
        q_(nullptr), a_(alpha)
    {}

    void start(const std::vector<scalar>& q)
    {
        q_ = q.data();
        phi_.assign(q.size(), 0);
    }

    void visit
    (
        const label s, const label m, const label* bt,
        const scalar*, const scalar*, const scalar*, const scalar* br
    )
    {
        scalar phii = 0;
        for (label j = 0; j < m; ++j)
        {
            const label t = bt[j];
            const scalar r = std::sqrt(br[j]);
            const scalar e = std::erfc(a_*r)/r;
            phii += q_[t]*e;
            phi_[t] += q_[s]*e;
        }
        phi_[s] += phii;
    }

    void finish(const std::vector<label>& order, Foam::UList<scalar>& phi)
    {
        for (size_t s = 0; s < order.size(); ++s)
        {
            phi[order[s]] += phi_[s];
        }
    }
};


// value(y) at the received charges xr, grouped by the processor they came
// from (fromProc[proci] of them, in order)
template<class Type, class Value>
Foam::List<Foam::List<Type>> valuesBySender
(
    const Foam::UList<Foam::point>& xr,
    const Foam::labelList& fromProc,
    const Value& value
)
{
    Foam::List<Foam::List<Type>> values(fromProc.size());
    label k = 0;
    forAll(values, proci)
    {
        values[proci].setSize(fromProc[proci]);
        for (Type& v : values[proci])
        {
            v = value(xr[k++]);
        }
    }
    return values;
}


// What the processors whose slabs a charge's stencil touched computed for
// it (values[proci][j] for the charge sent[proci][j]), sent back to its
// owner, which calls add(i, value) for each
template<class Type, class Add>
void returnFromSlabs
(
    Foam::List<Foam::List<Type>>& values,
    const Foam::List<Foam::DynamicList<label>>& sent,
    const Add& add
)
{
    Foam::labelList backSizes(sent.size());
    forAll(sent, proci)
    {
        backSizes[proci] = sent[proci].size();
    }
    Foam::List<Foam::List<Type>> received;
    Foam::Pstream::exchange<Foam::List<Type>, Type>
    (
        values, backSizes, received
    );
    forAll(received, proci)
    {
        forAll(sent[proci], j)
        {
            add(sent[proci][j], received[proci][j]);
        }
    }
}


// Per axis of P3M's mesh (length L, n points, nk wave numbers, order P,
// aliases |b| <= nb): the wave numbers k1, their ik-differentiation
// values kd (zero at the Nyquist plane: a real field), the alias sum of
// U^2 den (closed form, Poisson summation: sum_m U^2(k + 2pi m/h) =
// sum_j M_2P(P + j) cos(k h j)), and each alias's U^2 and wave number
struct axisTables
{
    std::vector<scalar> k1, kd, den;
    std::vector<std::vector<scalar>> U2a, ka;
};

axisTables axisTablesFor
(
    const scalar L,
    const label n,
    const label nk,
    const label P,
    const label nb
)
{
    using Foam::constant::mathematical::twoPi;
    std::vector<scalar> M2P(2*P);
    bspline(2*P, 0, M2P.data());
    const scalar h = L/n;
    axisTables t;
    t.k1.resize(nk);
    t.kd.resize(nk);
    t.den.resize(nk);
    t.U2a.assign(nk, std::vector<scalar>(2*nb + 1));
    t.ka.assign(nk, std::vector<scalar>(2*nb + 1));
    for (label i = 0; i < nk; ++i)
    {
        const label m = (i <= n/2) ? i : i - n;
        const scalar k = twoPi*m/L;
        t.k1[i] = k;
        t.kd[i] = (2*i == n) ? 0 : k;
        scalar s = M2P[P];
        for (label j = 1; j < P; ++j)
        {
            s += 2*M2P[P + j]*Foam::cos(k*h*j);
        }
        t.den[i] = s;
        for (label b = -nb; b <= nb; ++b)
        {
            const scalar kb = k + twoPi*b/h;
            const scalar x = 0.5*kb*h;
            const scalar sinc = (x == 0) ? 1 : Foam::sin(x)/x;
            t.U2a[i][b + nb] = Foam::pow(sinc, 2*P);
            t.ka[i][b + nb] = kb;
        }
    }
    return t;
}


} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::p3m::p3m
(
    const vector& L,
    const scalar epsilonR,
    const scalar accuracy,
    const label order
)
:
    periodicElectrostatics(L, epsilonR),
    accuracy_(accuracy),
    order_(order),
    rCutUser_(0),
    alphaUser_(0),
    meshUser_{0, 0, 0},
    fastErfcUser_(-1),
    ready_(false),
    N0_(-1),
    Q20_(-1),
    rho_(nullptr),
    Efield_{nullptr, nullptr, nullptr},
    rhoHat_(nullptr),
    work_(nullptr),
    planForward_(nullptr),
    planBackward_{nullptr, nullptr, nullptr},
    distributed_(false),
    local0_(0),
    localN0_(0),
    local1_(0),
    localN1_(0),
    nLocal_(0),
    nHalo_(0),
    timeReal_(0),
    timeKspace_(0)
{
    if (!(accuracy > 0) || !(accuracy <= 0.1))
    {
        FatalErrorInFunction
            << "P3M accuracy = " << accuracy << " is out of range (0, 0.1]"
            << exit(FatalError);
    }
    if (order < 1 || order > 7)
    {
        FatalErrorInFunction
            << "P3M assignment order = " << order << " is out of range"
            << " [1, 7]" << exit(FatalError);
    }
}


Foam::p3m::p3m(const dictionary& dict)
:
    periodicElectrostatics(readBox(dict), readEpsilonR(dict)),
    accuracy_(readScalar(dict, "accuracy", 1e-4, 0, 0.1)),
    order_(readLabel(dict, "order", 5, 1, 7)),
    rCutUser_(dict.getOrDefault<scalar>("rCut", 0)),
    alphaUser_
    (
        getCheckedOrDefault<scalar>
        (
            dict, "alpha", 0,
            [](const scalar x) { return x >= 0 && std::isfinite(x); },
            " [0, inf) (0: automatic)"
        )
    ),
    meshUser_{0, 0, 0},
    fastErfcUser_(readFastErfc(dict)),
    ready_(false),
    N0_(-1),
    Q20_(-1),
    rho_(nullptr),
    Efield_{nullptr, nullptr, nullptr},
    rhoHat_(nullptr),
    work_(nullptr),
    planForward_(nullptr),
    planBackward_{nullptr, nullptr, nullptr},
    distributed_(false),
    local0_(0),
    localN0_(0),
    local1_(0),
    localN1_(0),
    nLocal_(0),
    nHalo_(0),
    timeReal_(0),
    timeKspace_(0)
{
    if (!(rCutUser_ >= 0 && rCutUser_ <= 0.5*cmptMin(L_)))
    {
        FatalIOErrorInFunction(dict)
            << "Entry 'rCut' = " << rCutUser_ << " is out of range [0, "
            << 0.5*cmptMin(L_) << "] (0: automatic; at most L/2)"
            << exit(FatalIOError);
    }
    if (dict.found("mesh"))
    {
        ITstream& is = dict.lookup("mesh");
        token t(is);
        if (t.isNumber())
        {
            meshUser_[0] = meshUser_[1] = meshUser_[2] = label(t.number());
        }
        else
        {
            is.putBack(t);
            Vector<label> m;
            is >> m;
            for (direction d = 0; d < 3; ++d) meshUser_[d] = m[d];
        }
        for (direction d = 0; d < 3; ++d)
        {
            if (meshUser_[d] < 0 || meshUser_[d] > 4096)
            {
                FatalIOErrorInFunction(dict)
                    << "Entry 'mesh' has " << meshUser_[d] << " points,"
                    << " out of range [0, 4096] (0: automatic)"
                    << exit(FatalIOError);
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::p3m::~p3m()
{
    clear();
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::p3m::clear() const
{
    if (planForward_)
    {
        fftw_destroy_plan(static_cast<fftw_plan>(planForward_));
        for (direction d = 0; d < 3; ++d)
        {
            fftw_destroy_plan(static_cast<fftw_plan>(planBackward_[d]));
            fftw_free(Efield_[d]);
            Efield_[d] = nullptr;
            planBackward_[d] = nullptr;
        }
        fftw_free(rho_);
        fftw_free(rhoHat_);
        fftw_free(work_);
        rho_ = nullptr;
        rhoHat_ = work_ = planForward_ = nullptr;
    }
    ready_ = false;
}


void Foam::p3m::estimateError
(
    const vector& L,
    const scalar k,
    const label N,
    const scalar Q2,
    parameters& p
)
{
    const scalar V = L.x()*L.y()*L.z();
    const scalar a = p.alpha;

    // Kolafa & Perram (1992): rms real-space force error
    p.errorReal =
        2*k*Q2*Foam::exp(-sqr(a*p.rCut))/Foam::sqrt(N*p.rCut*V);

    // Deserno & Holm (1998 II), closed form per direction
    scalar e2 = 0;
    for (direction d = 0; d < 3; ++d)
    {
        const scalar ha = L[d]/p.mesh[d]*a;
        scalar sum = 0;
        for (label m = 0; m < p.order; ++m)
        {
            sum += acons[p.order][m]*Foam::pow(ha, 2.0*m);
        }
        const scalar ed =
            k*Q2*Foam::pow(ha, scalar(p.order))
           *Foam::sqrt(a*L[d]*Foam::sqrt(twoPi)*sum/N)/sqr(L[d]);
        e2 += ed*ed;
    }
    p.errorKspace = Foam::sqrt(e2/3);
    p.error = Foam::sqrt(sqr(p.errorReal) + sqr(p.errorKspace));
}


void Foam::p3m::setup
(
    const label N,
    const scalar Q2,
    const bool distributed
) const
{
    clear();
    tab_.clear();
    chooseParameters(N, Q2);
    allocateMesh(distributed);
    influenceFunction();

    N0_ = N;
    Q20_ = Q2;
    ready_ = true;
}


void Foam::p3m::chooseParameters(const label N, const scalar Q2) const
{

    const scalar V = L_.x()*L_.y()*L_.z();
    const scalar n = N/V;
    const scalar spacing = std::cbrt(1.0/n);
    const scalar Lmin = cmptMin(L_);
    const label P = order_;

    // Requested absolute rms error, split evenly between the two parts
    const scalar target = accuracy_*k_*Q2/N*Foam::pow(n, 2.0/3.0);
    const scalar eps = target/Foam::sqrt(2.0);

    std::vector<scalar> rcs;
    if (rCutUser_ > 0)
    {
        rcs.push_back(rCutUser_);
    }
    else
    {
        for (scalar c = 1.5; c <= 6.01; c += 0.25)
        {
            rcs.push_back(std::min(c*spacing, Lmin/3));
        }
        if (rcs.back() < 1.5*spacing)
        {
            // Few particles: the all-pairs fallback allows up to L/2
            rcs.push_back(Lmin/2);
        }
    }

    // Largest automatic mesh per direction: 256^3 points take ~0.8 GB
    const label maxMesh = 256;

    parameters best;
    best.error = GREAT;
    scalar bestCost = GREAT;
    bool bestFeasible = false;
    for (const scalar rc : rcs)
    {
        parameters p;
        p.order = P;
        p.rCut = rc;
        p.target = target;
        if (alphaUser_ > 0)
        {
            p.alpha = alphaUser_;
        }
        else
        {
            // Invert Kolafa-Perram for dF_real = eps
            const scalar arg = eps*Foam::sqrt(N*rc*V)/(2*k_*Q2);
            p.alpha = Foam::sqrt(-Foam::log(std::min(arg, 0.5)))/rc;
        }

        // Mesh per direction: smallest FFT size meeting eps
        for (direction d = 0; d < 3; ++d)
        {
            if (meshUser_[d] > 0)
            {
                p.mesh[d] = meshUser_[d];
                continue;
            }
            label m = fftSize(std::max(label(4), P));
            while (true)
            {
                // Error of direction d alone: the estimate is per direction
                const scalar ha = L_[d]/m*p.alpha;
                scalar sum = 0;
                for (label j = 0; j < P; ++j)
                {
                    sum += acons[P][j]*Foam::pow(ha, 2.0*j);
                }
                const scalar ed =
                    k_*Q2*Foam::pow(ha, scalar(P))
                   *Foam::sqrt(p.alpha*L_[d]*Foam::sqrt(twoPi)*sum/N)
                   /sqr(L_[d]);
                if (ed <= eps || m >= maxMesh) break;
                m = fftSize(m + 1);
            }
            p.mesh[d] = m;
        }
        p.fastErfc =
            (fastErfcUser_ < 0) ? (accuracy_ >= 1e-5) : (fastErfcUser_ > 0);
        estimateError(L_, k_, N, Q2, p);

        // Cost model [ns], calibrated roughly on one core: pair checks of
        // the 27-cell stencil, accepted pairs (erfc, exp), assignment and
        // interpolation (4 P^3 per particle), 4 FFTs
        const scalar nPairsChecked = 0.5*27*Foam::pow(rc, 3)*n*N;
        const scalar nPairs = (2*pi/3)*Foam::pow(rc, 3)*n*N;
        const scalar M = scalar(p.mesh[0])*p.mesh[1]*p.mesh[2];
        const scalar cost =
            1.0*nPairsChecked + 8.0*nPairs
          + 1.5*4*Foam::pow(scalar(P), 3)*N
          + 4*2.0*M*Foam::log(M)/Foam::log(2.0) + 5*M;
        // Infeasible (mesh cap reached): keep the most accurate instead
        const bool feasible = p.error <= 1.001*target;
        if
        (
            (feasible && (!bestFeasible || cost < bestCost))
         || (!feasible && !bestFeasible && p.error < best.error)
        )
        {
            bestCost = feasible ? cost : bestCost;
            bestFeasible = feasible;
            best = p;
        }
    }
    p_ = best;
    if (!bestFeasible)
    {
        WarningInFunction
            << "P3M cannot meet accuracy " << accuracy_ << " with order "
            << P << " and at most " << maxMesh << " mesh points per"
            << " direction: estimated rms error " << p_.error
            << " N > target " << target << " N. Raise the order or rCut."
            << endl;
    }

}


void Foam::p3m::allocateMesh(const bool distributed) const
{
    // FFTW arrays and plans; planning with MEASURE overwrites the arrays
    const label n0 = p_.mesh[0], n1 = p_.mesh[1], n2 = p_.mesh[2];
    const label nReal = n0*n1*n2;
    const label nCplx = n0*n1*(n2/2 + 1);
    const unsigned flags = (nReal > 32768) ? FFTW_MEASURE : FFTW_ESTIMATE;

    distributed_ = distributed;
    if (distributed)
    {
        // Slabs of x-planes (real mesh) and y-planes (transposed
        // transform: no transpose back, the influence function is applied
        // in that order), padded real rows of 2 (n2/2 + 1) (FFTW MPI r2c)
        static bool fftwMpiReady = false;
        if (!fftwMpiReady)
        {
            fftw_mpi_init();
            fftwMpiReady = true;
        }
        ptrdiff_t ln0, l0, ln1, l1;
        const ptrdiff_t nLocal = fftw_mpi_local_size_3d_transposed
        (
            n0, n1, n2/2 + 1, MPI_COMM_WORLD, &ln0, &l0, &ln1, &l1
        );
        local0_ = l0;
        localN0_ = ln0;
        local1_ = l1;
        localN1_ = ln1;

        labelList starts(Pstream::nProcs(), 0), counts(Pstream::nProcs(), 0);
        starts[Pstream::myProcNo()] = local0_;
        counts[Pstream::myProcNo()] = localN0_;
        Pstream::listCombineGather(starts, plusEqOp<label>());
        Pstream::listCombineScatter(starts);
        Pstream::listCombineGather(counts, plusEqOp<label>());
        Pstream::listCombineScatter(counts);
        planeOwner_.setSize(n0);
        forAll(starts, proci)
        {
            for (label i = 0; i < counts[proci]; ++i)
            {
                planeOwner_[starts[proci] + i] = proci;
            }
        }

        // FFTW_ESTIMATE: MEASURE's trial transforms are collectives whose
        // choice depends on timing, so the plan (round-off) and the
        // traffic would differ from run to run
        const unsigned mpiFlags = FFTW_ESTIMATE;
        const size_t nAlloc = std::max(ptrdiff_t(1), nLocal);
        rho_ = fftw_alloc_real(2*nAlloc);
        for (direction d = 0; d < 3; ++d)
        {
            Efield_[d] = fftw_alloc_real(2*nAlloc);
        }
        rhoHat_ = fftw_alloc_complex(nAlloc);
        work_ = fftw_alloc_complex(nAlloc);
        planForward_ = fftw_mpi_plan_dft_r2c_3d
        (
            n0, n1, n2, rho_, static_cast<fftw_complex*>(rhoHat_),
            MPI_COMM_WORLD, mpiFlags | FFTW_MPI_TRANSPOSED_OUT
        );
        for (direction d = 0; d < 3; ++d)
        {
            planBackward_[d] = fftw_mpi_plan_dft_c2r_3d
            (
                n0, n1, n2, static_cast<fftw_complex*>(work_), Efield_[d],
                MPI_COMM_WORLD,
                mpiFlags | FFTW_DESTROY_INPUT | FFTW_MPI_TRANSPOSED_IN
            );
        }
        return;
    }

    local0_ = 0;
    localN0_ = n0;
    local1_ = 0;
    localN1_ = n1;
    rho_ = fftw_alloc_real(nReal);
    for (direction d = 0; d < 3; ++d) Efield_[d] = fftw_alloc_real(nReal);
    rhoHat_ = fftw_alloc_complex(nCplx);
    work_ = fftw_alloc_complex(nCplx);
    planForward_ = fftw_plan_dft_r2c_3d
    (
        n0, n1, n2, rho_, static_cast<fftw_complex*>(rhoHat_), flags
    );
    for (direction d = 0; d < 3; ++d)
    {
        planBackward_[d] = fftw_plan_dft_c2r_3d
        (
            n0, n1, n2, static_cast<fftw_complex*>(work_), Efield_[d],
            flags | FFTW_DESTROY_INPUT
        );
    }
}


void Foam::p3m::influenceFunction(const bool withPotential) const
{
    const label P = p_.order;
    const label n[3] = {p_.mesh[0], p_.mesh[1], p_.mesh[2]};
    const scalar a = p_.alpha;
    const scalar V = L_.x()*L_.y()*L_.z();

    // Aliasing range as LAMMPS' PPPM (terms below ~1e-7), at least 1
    label nb[3];
    for (direction d = 0; d < 3; ++d)
    {
        nb[d] = std::max
        (
            label(1),
            label(a*L_[d]/(pi*n[d])*Foam::pow(-Foam::log(1e-7), 0.25))
        );
    }

    axisTables t[3];
    for (direction d = 0; d < 3; ++d)
    {
        t[d] = axisTablesFor
        (
            L_[d], n[d], (d == 2) ? n[d]/2 + 1 : n[d], P, nb[d]
        );
    }

    // Serial: all of it, (i0, i1, i2) order; distributed: this
    // processor's y-planes, (i1, i0, i2) order (transposed transform)
    const label n2c = n[2]/2 + 1;
    const label i1Begin = local1_, i1End = local1_ + localN1_;
    G_.assign((i1End - i1Begin)*n[0]*n2c, 0);
    if (withPotential)
    {
        Gphi_.assign(G_.size(), 0);
    }
    else
    {
        Gphi_.clear();
    }
    kx_ = t[0].kd;
    ky_ = t[1].kd;
    kz_ = t[2].kd;
    const scalar c4a2 = 1.0/(4*a*a);

    for (label i0 = 0; i0 < n[0]; ++i0)
    {
        for (label i1 = i1Begin; i1 < i1End; ++i1)
        {
            for (label i2 = 0; i2 < n2c; ++i2)
            {
                const vector k(t[0].k1[i0], t[1].k1[i1], t[2].k1[i2]);
                const scalar k2 = magSqr(k);
                if (k2 == 0) continue;
                scalar num = 0, numPhi = 0;
                for (label b0 = 0; b0 <= 2*nb[0]; ++b0)
                {
                    const scalar u0 = t[0].U2a[i0][b0];
                    const scalar q0 = t[0].ka[i0][b0];
                    for (label b1 = 0; b1 <= 2*nb[1]; ++b1)
                    {
                        const scalar u01 = u0*t[1].U2a[i1][b1];
                        const scalar q1 = t[1].ka[i1][b1];
                        for (label b2 = 0; b2 <= 2*nb[2]; ++b2)
                        {
                            const scalar q2 = t[2].ka[i2][b2];
                            const scalar kb2 = q0*q0 + q1*q1 + q2*q2;
                            const scalar dot =
                                k.x()*q0 + k.y()*q1 + k.z()*q2;
                            num +=
                                u01*t[2].U2a[i2][b2]*dot/kb2
                               *Foam::exp(-kb2*c4a2);
                            if (withPotential)
                            {
                                numPhi +=
                                    u01*t[2].U2a[i2][b2]/kb2
                                   *Foam::exp(-kb2*c4a2);
                            }
                        }
                    }
                }
                const scalar D = t[0].den[i0]*t[1].den[i1]*t[2].den[i2];
                const label c =
                    distributed_
                  ? ((i1 - i1Begin)*n[0] + i0)*n2c + i2
                  : (i0*n[1] + i1)*n2c + i2;
                G_[c] = 4*pi*num/(k2*D*D)/V;
                if (withPotential)
                {
                    // Optimal for the potential (Hockney & Eastwood
                    // 8-22 with the potential's Green function)
                    Gphi_[c] = 4*pi*numPhi/(D*D)/V;
                }
            }
        }
    }
}


Foam::label Foam::p3m::realSpaceCells(label nc[3]) const
{
    // Cells of rc/2 (5^3 stencil: 27 % of the visited volume within rc,
    // vs 15 % for cells of rc), else rc, else all pairs
    const scalar rc = p_.rCut;
    label reach = 2;
    for (direction d = 0; d < 3; ++d)
    {
        nc[d] = label(2*L_[d]/rc);
        if (nc[d] < 5) reach = 1;
    }
    if (reach == 1)
    {
        for (direction d = 0; d < 3; ++d) nc[d] = label(L_[d]/rc);
    }
    return (nc[0] < 3 || nc[1] < 3 || nc[2] < 3) ? 0 : reach;
}


template<class Visitor, class Result>
void Foam::p3m::realSpacePairs
(
    const UList<point>& xw,
    const UList<scalar>& q,
    const label nOwn,
    Visitor& v,
    UList<Result>& result
) const
{
    const label N = xw.size();
    // Pairs of two copies (a halo's) give nothing this processor keeps
    const label nKept = nOwn < 0 ? N : nOwn;
    const scalar rc = p_.rCut, rc2 = rc*rc;

    label nc[3];
    const label reach = realSpaceCells(nc);
    if (!reach)
    {
        // Few cells: all pairs, minimum image (rc <= L/2 is checked)
        std::vector<label> order(N);
        std::vector<scalar> qs(N);
        for (label i = 0; i < N; ++i)
        {
            order[i] = i;
            qs[i] = q[i];
        }
        v.start(qs);
        for (label i = 0; i < N; ++i)
        {
            std::vector<label> bt;
            std::vector<scalar> bx, by, bz, br;
            for (label j = i + 1; j < N; ++j)
            {
                const vector r = minImage(xw[i] - xw[j]);
                const scalar r2 = magSqr(r);
                if (r2 >= rc2 || (i >= nKept && j >= nKept)) continue;
                if (r2 == 0)
                {
                    FatalErrorInFunction
                        << "Charges " << i << " and " << j << " coincide"
                        << exit(FatalError);
                }
                bt.push_back(j);
                bx.push_back(r.x());
                by.push_back(r.y());
                bz.push_back(r.z());
                br.push_back(r2);
            }
            v.visit
            (
                i, bt.size(), bt.data(), bx.data(), by.data(), bz.data(),
                br.data()
            );
        }
        v.finish(order, result);
        return;
    }

    // Cell list, charges sorted by cell
    const cellSortedCharges sorted(xw, q, nKept, L_, nc);
    v.start(sorted.qs);
    cellPairs(sorted, L_, reach, rc2, v);
    v.finish(sorted.order, result);
}


void Foam::p3m::realSpace
(
    const UList<point>& xw,
    const UList<scalar>& q,
    UList<vector>& f,
    const label nOwn
) const
{
    const label N = xw.size();
    // Pairs of two copies (a halo's) give nothing this processor keeps
    const label nKept = nOwn < 0 ? N : nOwn;
    const scalar rc = p_.rCut, rc2 = rc*rc;
    const realSpaceForce pairForce(p_.alpha, rc, p_.fastErfc, tab_);

    label nc[3];
    const label reach = realSpaceCells(nc);
    if (!reach)
    {
        // Few cells: all pairs, minimum image (rc <= L/2 is checked)
        for (label i = 0; i < N; ++i)
        {
            vector fi(Zero);
            for (label j = i + 1; j < N; ++j)
            {
                const vector r = minImage(xw[i] - xw[j]);
                const scalar r2 = magSqr(r);
                if (r2 >= rc2 || (i >= nKept && j >= nKept)) continue;
                if (r2 == 0)
                {
                    FatalErrorInFunction
                        << "Charges " << i << " and " << j << " coincide"
                        << exit(FatalError);
                }
                const vector fij = (q[i]*q[j]*pairForce(r2))*r;
                fi += fij;
                f[j] -= fij;
            }
            f[i] += fi;
        }
        return;
    }

    // Cell list, charges sorted by cell
    const cellSortedCharges sorted(xw, q, nKept, L_, nc);
    std::vector<scalar> fx(N, 0), fy(N, 0), fz(N, 0);
    cellPairForces(sorted, L_, reach, rc2, pairForce, fx, fy, fz);
    for (label s = 0; s < N; ++s)
    {
        f[sorted.order[s]] += vector(fx[s], fy[s], fz[s]);
    }
}


void Foam::p3m::assign
(
    const UList<point>& xw,
    const UList<scalar>& q
) const
{
    const label P = p_.order;
    const label n1 = p_.mesh[1];
    const label stride = meshRowStride();
    const scalar hi[3] =
        {p_.mesh[0]/L_.x(), p_.mesh[1]/L_.y(), p_.mesh[2]/L_.z()};
    label idx[3][7];
    scalar w[3][7];

    std::fill(rho_, rho_ + localN0_*n1*stride, 0.0);
    forAll(xw, i)
    {
        assignmentStencil(xw[i], P, hi, p_.mesh, idx, w);
        const scalar qi = q[i];
        for (label a = 0; a < P; ++a)
        {
            // This processor's x-planes only (serial: all)
            const label i0 = idx[0][a] - local0_;
            if (i0 < 0 || i0 >= localN0_) continue;
            const scalar wa = qi*w[0][a];
            for (label b = 0; b < P; ++b)
            {
                const scalar wab = wa*w[1][b];
                double* row = rho_ + (i0*n1 + idx[1][b])*stride;
                for (label c = 0; c < P; ++c)
                {
                    row[idx[2][c]] += wab*w[2][c];
                }
            }
        }
    }
}


void Foam::p3m::solveMesh() const
{
    fftw_execute(static_cast<fftw_plan>(planForward_));

    // E_d = backward FFT of -i k_d G rho^ (G includes 1/V), in the
    // transform's order: (i0, i1, i2) serial, (i1, i0, i2) distributed
    const label n0 = p_.mesh[0], n1 = p_.mesh[1];
    const label n2c = p_.mesh[2]/2 + 1;
    const label nOuter = distributed_ ? localN1_ : n0;
    const label nMiddle = distributed_ ? n0 : n1;
    fftw_complex* rh = static_cast<fftw_complex*>(rhoHat_);
    fftw_complex* wk = static_cast<fftw_complex*>(work_);
    for (direction d = 0; d < 3; ++d)
    {
        for (label o = 0; o < nOuter; ++o)
        {
            for (label m = 0; m < nMiddle; ++m)
            {
                const label i0 = distributed_ ? m : o;
                const label i1 = distributed_ ? local1_ + o : m;
                const label base = (o*nMiddle + m)*n2c;
                for (label i2 = 0; i2 < n2c; ++i2)
                {
                    const label c = base + i2;
                    const scalar kd =
                        (d == 0) ? kx_[i0] : (d == 1) ? ky_[i1] : kz_[i2];
                    const scalar g = kd*G_[c];
                    wk[c][0] = g*rh[c][1];
                    wk[c][1] = -g*rh[c][0];
                }
            }
        }
        fftw_execute(static_cast<fftw_plan>(planBackward_[d]));
    }
}


void Foam::p3m::solvePotentialMesh() const
{
    if (Gphi_.size() != G_.size())
    {
        influenceFunction(true);
    }
    fftw_execute(static_cast<fftw_plan>(planForward_));

    // phi = backward FFT of Gphi rho^ into the first field mesh
    fftw_complex* rh = static_cast<fftw_complex*>(rhoHat_);
    fftw_complex* wk = static_cast<fftw_complex*>(work_);
    for (size_t c = 0; c < Gphi_.size(); ++c)
    {
        wk[c][0] = Gphi_[c]*rh[c][0];
        wk[c][1] = Gphi_[c]*rh[c][1];
    }
    fftw_execute(static_cast<fftw_plan>(planBackward_[0]));
}


template<int nMesh>
void Foam::p3m::interpolateMeshes
(
    const point& xw,
    const double* const* meshes,
    scalar* values
) const
{
    const label P = p_.order;
    const label n1 = p_.mesh[1];
    const label stride = meshRowStride();
    const scalar hi[3] =
        {p_.mesh[0]/L_.x(), p_.mesh[1]/L_.y(), p_.mesh[2]/L_.z()};
    label idx[3][7];
    scalar w[3][7];
    assignmentStencil(xw, P, hi, p_.mesh, idx, w);

    // The same weights as the assignment, on this processor's x-planes
    for (int v = 0; v < nMesh; ++v) values[v] = 0;
    for (label a = 0; a < P; ++a)
    {
        const label i0 = idx[0][a] - local0_;
        if (i0 < 0 || i0 >= localN0_) continue;
        for (label b = 0; b < P; ++b)
        {
            const scalar wab = w[0][a]*w[1][b];
            const label row = (i0*n1 + idx[1][b])*stride;
            for (label c = 0; c < P; ++c)
            {
                const scalar wabc = wab*w[2][c];
                const label m = row + idx[2][c];
                for (int v = 0; v < nMesh; ++v)
                {
                    values[v] += wabc*meshes[v][m];
                }
            }
        }
    }
}


Foam::vector Foam::p3m::interpolate(const point& xw) const
{
    vector E;
    interpolateMeshes<3>(xw, Efield_, E.v_);
    return E;
}


Foam::scalar Foam::p3m::interpolatePotential(const point& xw) const
{
    scalar phi;
    interpolateMeshes<1>(xw, Efield_, &phi);
    return phi;
}


void Foam::p3m::kSpace
(
    const UList<point>& xw,
    const UList<scalar>& q,
    UList<vector>& f
) const
{
    assign(xw, q);
    solveMesh();
    forAll(xw, i)
    {
        f[i] += q[i]*interpolate(xw[i]);
    }
}


Foam::List<Foam::point> Foam::p3m::assignOnSlabs
(
    const UList<point>& xw,
    const UList<scalar>& q,
    List<DynamicList<label>>& sent,
    labelList& fromProc
) const
{
    const label nProcs = Pstream::nProcs();
    const label P = p_.order;
    const scalar hi[3] =
        {p_.mesh[0]/L_.x(), p_.mesh[1]/L_.y(), p_.mesh[2]/L_.z()};
    label idx[3][7];
    scalar w[3][7];

    // Each charge to the processors whose x-planes its stencil touches
    sent.setSize(nProcs);
    forAll(xw, i)
    {
        assignmentStencil(xw[i], P, hi, p_.mesh, idx, w);
        label owners[7];
        label nOwners = 0;
        for (label a = 0; a < P; ++a)
        {
            const label o = planeOwner_[idx[0][a]];
            if (std::find(owners, owners + nOwners, o) == owners + nOwners)
            {
                owners[nOwners++] = o;
            }
        }
        for (label k = 0; k < nOwners; ++k)
        {
            sent[owners[k]].append(i);
        }
    }
    List<List<point>> sendX(nProcs), recvX;
    List<List<scalar>> sendQ(nProcs), recvQ;
    forAll(sent, proci)
    {
        sendX[proci] = UIndirectList<point>(xw, sent[proci]);
        sendQ[proci] = UIndirectList<scalar>(q, sent[proci]);
    }
    labelList recvSizes;
    Pstream::exchangeSizes(sendX, recvSizes);
    Pstream::exchange<List<point>, point>(sendX, recvSizes, recvX);
    Pstream::exchange<List<scalar>, scalar>(sendQ, recvSizes, recvQ);

    // Assigned on this processor's slab
    List<point> xr(ListListOps::combine<List<point>>
    (
        recvX, accessOp<List<point>>()
    ));
    assign
    (
        xr,
        ListListOps::combine<List<scalar>>(recvQ, accessOp<List<scalar>>())
    );
    fromProc.setSize(nProcs);
    forAll(recvX, proci)
    {
        fromProc[proci] = recvX[proci].size();
    }
    return xr;
}


void Foam::p3m::kSpaceDistributed
(
    const UList<point>& xw,
    const UList<scalar>& q,
    UList<vector>& f
) const
{
    List<DynamicList<label>> sent;
    labelList fromProc;
    const List<point> xr(assignOnSlabs(xw, q, sent, fromProc));
    solveMesh();

    // This slab's part of each received charge's field, sent back
    List<List<vector>> sendE(valuesBySender<vector>
    (
        xr, fromProc, [this](const point& y) { return interpolate(y); }
    ));
    returnFromSlabs
    (
        sendE, sent,
        [&](const label i, const vector& E) { f[i] += q[i]*E; }
    );
}


void Foam::p3m::kSpacePotential
(
    const UList<point>& xw,
    const UList<scalar>& q,
    UList<scalar>& phi
) const
{
    if (!distributed_)
    {
        assign(xw, q);
        solvePotentialMesh();
        forAll(xw, i)
        {
            phi[i] += interpolatePotential(xw[i]);
        }
        return;
    }

    List<DynamicList<label>> sent;
    labelList fromProc;
    const List<point> xr(assignOnSlabs(xw, q, sent, fromProc));
    solvePotentialMesh();
    List<List<scalar>> sendPhi(valuesBySender<scalar>
    (
        xr, fromProc, [this](const point& y) { return interpolatePotential(y); }
    ));
    returnFromSlabs
    (
        sendPhi, sent,
        [&](const label i, const scalar v) { phi[i] += v; }
    );
}


void Foam::p3m::addPotentialConstants
(
    const UList<scalar>& q,
    const scalar Qtotal,
    UList<scalar>& phi
) const
{
    // Ewald's self term -2 a q_i/sqrt(pi) (the mesh's potential includes
    // the charge's own Gaussian) and the background's -pi Q/(V a^2)
    // (d/dq_i of its energy -pi Q^2/(2 V a^2)); then k
    const scalar a = p_.alpha;
    const scalar V = L_.x()*L_.y()*L_.z();
    const scalar background = -pi*Qtotal/(V*a*a);
    forAll(phi, i)
    {
        phi[i] = k_*(phi[i] - 2*a/Foam::sqrt(pi)*q[i] + background);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::p3m::tune
(
    const label N,
    const scalar Q2,
    const bool distributed
) const
{
    if
    (
        !ready_
     || distributed != distributed_
     || mag(Foam::log(scalar(N)/N0_)) > 0.1
     || mag(Foam::log(Q2/Q20_)) > 0.1
    )
    {
        setup(N, Q2, distributed);
    }
}


const Foam::p3m::parameters& Foam::p3m::tune
(
    const label N,
    const scalar Q2
) const
{
    tune(N, Q2, distributed_ && ready_);
    return p_;
}


void Foam::p3m::compute
(
    const UList<point>& x,
    const UList<scalar>& q,
    List<vector>& f
) const
{
    checkInput(x, q);
    const label N = x.size();
    f.setSize(N);
    f = Zero;
    scalar Q2 = 0;
    for (const scalar qi : q) Q2 += qi*qi;
    if (N == 0 || Q2 == 0) return;

    tune(N, Q2, false);

    List<point> xw(N);
    forAll(x, i)
    {
        xw[i] = wrap(x[i]);
    }

    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    realSpace(xw, q, f);
    const auto t1 = clock::now();
    kSpace(xw, q, f);
    const auto t2 = clock::now();
    timeReal_ = std::chrono::duration<double>(t1 - t0).count();
    timeKspace_ = std::chrono::duration<double>(t2 - t1).count();

    forAll(f, i)
    {
        f[i] *= k_;
    }
}


void Foam::p3m::haloWithin
(
    const UList<point>& x,
    const UList<scalar>& q,
    const List<boundBox>& boxes,
    List<point>& xh,
    List<scalar>& qh
) const
{
    const processorHalo halo
    (
        boxes, x, p_.rCut, processorHalo::boxTranslations(L_)
    );
    qh = q;
    halo.gather(qh);
    xh = halo.points();
    forAll(xh, i)
    {
        xh[i] = wrap(xh[i]);
    }
}


void Foam::p3m::computeDistributed
(
    const UList<point>& x,
    const UList<scalar>& q,
    const List<boundBox>& boxes,
    List<vector>& f
) const
{
    if (!Pstream::parRun())
    {
        compute(x, q, f);
        return;
    }

    checkInput(x, q);
    if (boxes.size() != Pstream::nProcs())
    {
        FatalErrorInFunction
            << "computeDistributed needs every processor's box: "
            << boxes.size() << " boxes for " << Pstream::nProcs()
            << " processors" << exit(FatalError);
    }
    const label nLocal = x.size();
    f.setSize(nLocal);
    f = Zero;
    label N = nLocal;
    scalar Q2 = 0;
    for (const scalar qi : q) Q2 += qi*qi;
    reduce(N, sumOp<label>());
    reduce(Q2, sumOp<scalar>());
    if (N == 0 || Q2 == 0) return;

    tune(N, Q2, true);

    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();

    // Real space: this processor's charges and the others' within rCut of
    // its box (unwrapped positions: the halo finds them by the boxes and
    // the periodic translations), then all wrapped for the cell list
    List<point> xh;
    List<scalar> qh;
    haloWithin(x, q, boxes, xh, qh);
    nLocal_ = nLocal;
    nHalo_ = xh.size() - nLocal;
    List<vector> fh(xh.size(), Zero);
    realSpace(xh, qh, fh, nLocal);
    forAll(f, i)
    {
        f[i] = fh[i];
    }
    const auto t1 = clock::now();

    kSpaceDistributed(SubList<point>(xh, nLocal), q, f);
    const auto t2 = clock::now();
    timeReal_ = std::chrono::duration<double>(t1 - t0).count();
    timeKspace_ = std::chrono::duration<double>(t2 - t1).count();

    forAll(f, i)
    {
        f[i] *= k_;
    }
}


void Foam::p3m::potentials
(
    const UList<point>& x,
    const UList<scalar>& q,
    scalarField& phi
) const
{
    checkInput(x, q);
    const label N = x.size();
    phi.setSize(N);
    phi = 0;
    scalar Q2 = 0, Q = 0;
    for (const scalar qi : q)
    {
        Q2 += qi*qi;
        Q += qi;
    }
    if (N == 0 || Q2 == 0) return;

    tune(N, Q2, false);
    List<point> xw(N);
    forAll(x, i)
    {
        xw[i] = wrap(x[i]);
    }
    realSpacePotentialSum pairs(p_.alpha);
    realSpacePairs(xw, q, -1, pairs, phi);
    kSpacePotential(xw, q, phi);
    addPotentialConstants(q, Q, phi);
}


void Foam::p3m::potentialsDistributed
(
    const UList<point>& x,
    const UList<scalar>& q,
    const List<boundBox>& boxes,
    scalarField& phi
) const
{
    if (!Pstream::parRun())
    {
        potentials(x, q, phi);
        return;
    }

    checkInput(x, q);
    const label nLocal = x.size();
    phi.setSize(nLocal);
    phi = 0;
    label N = nLocal;
    scalar Q2 = 0, Q = 0;
    for (const scalar qi : q)
    {
        Q2 += qi*qi;
        Q += qi;
    }
    reduce(N, sumOp<label>());
    reduce(Q2, sumOp<scalar>());
    reduce(Q, sumOp<scalar>());
    if (N == 0 || Q2 == 0) return;

    tune(N, Q2, true);

    // Real space: own charges and the halo within rCut, as the forces
    List<point> xh;
    List<scalar> qh;
    haloWithin(x, q, boxes, xh, qh);
    scalarField phih(xh.size(), 0);
    realSpacePotentialSum pairs(p_.alpha);
    realSpacePairs(xh, qh, nLocal, pairs, phih);
    forAll(phi, i)
    {
        phi[i] = phih[i];
    }
    kSpacePotential(SubList<point>(xh, nLocal), q, phi);
    addPotentialConstants(q, Q, phi);
}


void Foam::p3m::writeInfo(Ostream& os) const
{
    periodicElectrostatics::writeInfo(os);
    os  << ", accuracy = " << accuracy_ << ", order = " << order_;
    if (ready_)
    {
        os  << " | tuned for N = " << N0_ << ": rCut = " << p_.rCut
            << ", alpha = " << p_.alpha << ", mesh = (" << p_.mesh[0] << ' '
            << p_.mesh[1] << ' ' << p_.mesh[2] << "), fastErfc = "
            << p_.fastErfc << ", estimated rms error = " << p_.error
            << " N (real " << p_.errorReal << ", kspace " << p_.errorKspace
            << "), target " << p_.target << " N";
        if (distributed_)
        {
            os  << " | distributed: x-planes " << local0_ << ".."
                << local0_ + localN0_ - 1 << " of " << p_.mesh[0]
                << " on this processor, " << nLocal_ << " own charges + "
                << nHalo_ << " of the halo (of " << N0_ << ")";
        }
    }
}


// ************************************************************************* //
