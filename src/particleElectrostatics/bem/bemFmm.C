/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bemFmm.H"
#include "simdClones.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <algorithm>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

using Foam::label;
using Foam::scalar;
using Foam::vector;

// Point-point kernels on arrays in tree order. Field x 4 pi: q d/|d|^3,
// potential x 4 pi: q/|d|. Mutual: one 1/r per pair serves both points.

// Points [a0, a1) with [b0, b1), a disjoint range of the same arrays
SIMD_CLONES
void p2pMutual
(
    const label a0, const label a1, const label b0, const label b1,
    const scalar* __restrict__ x, const scalar* __restrict__ y,
    const scalar* __restrict__ z, const scalar* __restrict__ q,
    scalar* __restrict__ ex, scalar* __restrict__ ey,
    scalar* __restrict__ ez, scalar* __restrict__ ph
)
{
    for (label i = a0; i < a1; ++i)
    {
        const scalar xi = x[i], yi = y[i], zi = z[i], qi = q[i];
        scalar exi = 0, eyi = 0, ezi = 0, phi = 0;
        #pragma omp simd reduction(+:exi, eyi, ezi, phi)
        for (label j = b0; j < b1; ++j)
        {
            const scalar dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
            const scalar ir = 1/std::sqrt(dx*dx + dy*dy + dz*dz);
            const scalar ir3 = ir*ir*ir;
            const scalar sj = q[j]*ir3, si = qi*ir3;
            exi += sj*dx; eyi += sj*dy; ezi += sj*dz; phi += q[j]*ir;
            ex[j] -= si*dx; ey[j] -= si*dy; ez[j] -= si*dz; ph[j] += qi*ir;
        }
        ex[i] += exi; ey[i] += eyi; ez[i] += ezi; ph[i] += phi;
    }
}


// All pairs within [a0, a1), each once
SIMD_CLONES
void p2pSelf
(
    const label a0, const label a1,
    const scalar* __restrict__ x, const scalar* __restrict__ y,
    const scalar* __restrict__ z, const scalar* __restrict__ q,
    scalar* __restrict__ ex, scalar* __restrict__ ey,
    scalar* __restrict__ ez, scalar* __restrict__ ph
)
{
    for (label i = a0; i < a1 - 1; ++i)
    {
        p2pMutual(i, i + 1, i + 1, a1, x, y, z, q, ex, ey, ez, ph);
    }
}


// As p2pMutual / p2pSelf (b0 < 0: within [a0, a1)), skipping pairs of the
// same group
SIMD_CLONES
void p2pGroups
(
    const label a0, const label a1, label b0, label b1,
    const scalar* __restrict__ x, const scalar* __restrict__ y,
    const scalar* __restrict__ z, const scalar* __restrict__ q,
    const label* __restrict__ g,
    scalar* __restrict__ ex, scalar* __restrict__ ey,
    scalar* __restrict__ ez, scalar* __restrict__ ph
)
{
    const bool self = b0 < 0;
    for (label i = a0; i < a1; ++i)
    {
        if (self)
        {
            b0 = i + 1;
            b1 = a1;
        }
        const scalar xi = x[i], yi = y[i], zi = z[i], qi = q[i];
        const label gi = g[i];
        scalar exi = 0, eyi = 0, ezi = 0, phi = 0;
        for (label j = b0; j < b1; ++j)
        {
            if (g[j] == gi) continue;
            const scalar dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
            const scalar ir = 1/std::sqrt(dx*dx + dy*dy + dz*dz);
            const scalar ir3 = ir*ir*ir;
            const scalar sj = q[j]*ir3, si = qi*ir3;
            exi += sj*dx; eyi += sj*dy; ezi += sj*dz; phi += q[j]*ir;
            ex[j] -= si*dx; ey[j] -= si*dy; ez[j] -= si*dz; ph[j] += qi*ir;
        }
        ex[i] += exi; ey[i] += eyi; ez[i] += ezi; ph[i] += phi;
    }
}


// Targets [a0, a1) of one tree from the sources [b0, b1) of another
SIMD_CLONES
void p2pOneWay
(
    const label a0, const label a1, const label b0, const label b1,
    const scalar* __restrict__ tx, const scalar* __restrict__ ty,
    const scalar* __restrict__ tz,
    const scalar* __restrict__ x, const scalar* __restrict__ y,
    const scalar* __restrict__ z, const scalar* __restrict__ q,
    scalar* __restrict__ ex, scalar* __restrict__ ey,
    scalar* __restrict__ ez, scalar* __restrict__ ph
)
{
    for (label i = a0; i < a1; ++i)
    {
        const scalar xi = tx[i], yi = ty[i], zi = tz[i];
        scalar exi = 0, eyi = 0, ezi = 0, phi = 0;
        #pragma omp simd reduction(+:exi, eyi, ezi, phi)
        for (label j = b0; j < b1; ++j)
        {
            const scalar dx = xi - x[j], dy = yi - y[j], dz = zi - z[j];
            const scalar ir = 1/std::sqrt(dx*dx + dy*dy + dz*dz);
            const scalar sj = q[j]*ir*ir*ir;
            exi += sj*dx; eyi += sj*dy; ezi += sj*dz; phi += q[j]*ir;
        }
        ex[i] += exi; ey[i] += eyi; ez[i] += ezi; ph[i] += phi;
    }
}


// Compile-time M2L kernels (mutual, orders 1..maxTemplateOrder). The loops
// of the M2L over the pairs of multi-indices (n, k), |n| + |k| <= p, are
// unrolled by templates, so that every index is a constant (no index
// tables, no gathers) and each row sum is a balanced sum tree (no serial
// chain of additions). Same arithmetic as the table-driven loops of
// bemFmm::derivatives and bemFmm::apply, which serve the other orders.

#define FMM_INLINE inline __attribute__((always_inline))

const label maxTemplateOrder = 8;

// Multi-indices numbered by degree d = a + b + c, then a = d..0, b = d-a..0:
// number of multi-indices of degree <= q (0 for q = -1)
constexpr label nCoef(const label q)
{
    return (q + 1)*(q + 2)*(q + 3)/6;
}

constexpr label indexOf(const label a, const label b, const label c)
{
    return nCoef(a + b + c - 1) + (b + c)*(b + c + 1)/2 + c;
}

// Components of the multi-index numbered i
constexpr label degOf(const label i, const label d = 0)
{
    return i < nCoef(d) ? d : degOf(i, d + 1);
}

constexpr label posOf(const label i)
{
    return i - nCoef(degOf(i) - 1);
}

constexpr label bcOf(const label r, const label s = 0)   // b + c
{
    return (s + 1)*(s + 2)/2 > r ? s : bcOf(r, s + 1);
}

constexpr label cOf(const label i)
{
    return posOf(i) - bcOf(posOf(i))*(bcOf(posOf(i)) + 1)/2;
}

constexpr label bOf(const label i)
{
    return bcOf(posOf(i)) - cOf(i);
}

constexpr label aOf(const label i)
{
    return degOf(i) - bcOf(posOf(i));
}

constexpr label sumIndex(const label i, const label j)
{
    return indexOf(aOf(i) + aOf(j), bOf(i) + bOf(j), cOf(i) + cOf(j));
}

// Recurrence data of the multi-index i > 0 (as bemFmm::multiIndex)
constexpr label dimOf(const label i)
{
    return aOf(i) > 0 ? 0 : bOf(i) > 0 ? 1 : 2;
}

constexpr label compOf(const label i, const label d)
{
    return d == 0 ? aOf(i) : d == 1 ? bOf(i) : cOf(i);
}

constexpr label lowerOf(const label i, const label s)   // i - s e_dim
{
    return indexOf
    (
        aOf(i) - (dimOf(i) == 0 ? s : 0),
        bOf(i) - (dimOf(i) == 1 ? s : 0),
        cOf(i) - (dimOf(i) == 2 ? s : 0)
    );
}


// McMurchie-Davidson level j: cur[i] = (n_d - 1) up[i - 2e_d]
// + R_d up[i - e_d] for the multi-indices i in [I0, I0 + LEN)
template<int I0, int LEN>
struct mdLevel
{
    static FMM_INLINE void eval
    (
        const scalar* __restrict__ R, const scalar* __restrict__ up,
        scalar* __restrict__ cur
    )
    {
        mdLevel<I0, LEN/2>::eval(R, up, cur);
        mdLevel<I0 + LEN/2, LEN - LEN/2>::eval(R, up, cur);
    }
};

template<int I>
struct mdLevel<I, 1>
{
    static FMM_INLINE void eval
    (
        const scalar* __restrict__ R, const scalar* __restrict__ up,
        scalar* __restrict__ cur
    )
    {
        cur[I] =
            compOf(I, dimOf(I)) > 1
          ? (compOf(I, dimOf(I)) - 1)*up[lowerOf(I, 2)]
          + R[dimOf(I)]*up[lowerOf(I, 1)]
          : R[dimOf(I)]*up[lowerOf(I, 1)];
    }
};

// Levels j = J..0 (R^(j) for |n| <= P - j, from R^(j+1))
template<int P, int J>
struct mdLevels
{
    static FMM_INLINE void eval(const scalar* R, scalar* aux)
    {
        mdLevel<1, nCoef(P - J) - 1>::eval
        (
            R, aux + (J + 1)*nCoef(P), aux + J*nCoef(P)
        );
        mdLevels<P, J - 1>::eval(R, aux);
    }
};

template<int P>
struct mdLevels<P, -1>
{
    static FMM_INLINE void eval(const scalar*, scalar*)
    {}
};

// D[n] = D^n (1/r) at R for |n| <= P: aux holds R^(j) at aux + j nCoef(P);
// the first nCoef(P) entries are D
template<int P>
FMM_INLINE void derivativesT(const vector& Rv, scalar* __restrict__ aux)
{
    const scalar R[3] = {Rv.x(), Rv.y(), Rv.z()};
    const scalar ir2 = 1/(R[0]*R[0] + R[1]*R[1] + R[2]*R[2]);
    scalar f = std::sqrt(ir2);
    for (label j = 0; j <= P; ++j)
    {
        aux[j*nCoef(P)] = f;
        f *= -(2*j + 1)*ir2;
    }
    mdLevels<P, P - 1>::eval(R, aux);
}


// sum_{j in [J0, J0 + LEN)} M[j] D[index of (j + K)], a balanced sum tree
template<int K, int J0, int LEN>
struct rowSum
{
    static FMM_INLINE scalar eval
    (
        const scalar* __restrict__ M, const scalar* __restrict__ D
    )
    {
        return
            rowSum<K, J0, LEN/2>::eval(M, D)
          + rowSum<K, J0 + LEN/2, LEN - LEN/2>::eval(M, D);
    }
};

template<int K, int J>
struct rowSum<K, J, 1>
{
    static FMM_INLINE scalar eval
    (
        const scalar* __restrict__ M, const scalar* __restrict__ D
    )
    {
        return M[J]*D[sumIndex(K, J)];
    }
};

// Mutual M2L for the rows k in [K0, K0 + LEN) (see bemFmm::apply), with
// the signed multipoles Ms_n = (-1)^|n| M_n of the source s and the plain
// ones M of the target t:
//   Lt_k += sum_n Ms_n(s) D_{n+k},  Ls_k += (-1)^|k| sum_n M_n(t) D_{n+k}
template<int P, int K0, int LEN>
struct m2lRows
{
    static FMM_INLINE void eval
    (
        const scalar* D, const scalar* Mss, const scalar* Mt,
        scalar* Lt, scalar* Ls
    )
    {
        m2lRows<P, K0, LEN/2>::eval(D, Mss, Mt, Lt, Ls);
        m2lRows<P, K0 + LEN/2, LEN - LEN/2>::eval(D, Mss, Mt, Lt, Ls);
    }
};

template<int P, int K>
struct m2lRows<P, K, 1>
{
    static FMM_INLINE void eval
    (
        const scalar* __restrict__ D, const scalar* __restrict__ Mss,
        const scalar* __restrict__ Mt, scalar* __restrict__ Lt,
        scalar* __restrict__ Ls
    )
    {
        const scalar st = rowSum<K, 0, nCoef(P - degOf(K))>::eval(Mss, D);
        const scalar ss = rowSum<K, 0, nCoef(P - degOf(K))>::eval(Mt, D);
        Lt[K] += st;
        Ls[K] += (degOf(K) % 2 ? -ss : ss);
    }
};

template<int P>
SIMD_CLONES
void m2lMutualT
(
    const vector& R,
    const scalar* Mss,
    const scalar* Mt,
    scalar* Lt,
    scalar* Ls
)
{
    scalar aux[(P + 1)*nCoef(P)];
    derivativesT<P>(R, aux);
    m2lRows<P, 0, nCoef(P)>::eval(aux, Mss, Mt, Lt, Ls);
}

typedef void (*m2lKernel)
(
    const vector&, const scalar*, const scalar*, scalar*, scalar*
);

const m2lKernel m2lMutualKernels[maxTemplateOrder + 1] =
{
    nullptr, m2lMutualT<1>, m2lMutualT<2>, m2lMutualT<3>, m2lMutualT<4>,
    m2lMutualT<5>, m2lMutualT<6>, m2lMutualT<7>, m2lMutualT<8>
};

#undef FMM_INLINE

} // namespace


// * * * * * * * * * * * * * * * * * * Tree  * * * * * * * * * * * * * * * * //

Foam::label Foam::bemFmm::tree::split
(
    const label begin,
    const label end,
    const UList<point>& pts,
    const labelList& groups,
    const label leafSize
)
{
    const label id = cells.size();
    cell c;
    c.centre = Zero;
    c.radius = 0;
    c.begin = begin;
    c.end = end;
    c.nChild = 0;
    c.child[0] = c.child[1] = -1;
    c.gMin = labelMax;
    c.gMax = labelMin;
    point lo(GREAT, GREAT, GREAT), hi(-GREAT, -GREAT, -GREAT);
    for (label k = begin; k < end; ++k)
    {
        const point& x = pts[perm[k]];
        lo = min(lo, x);
        hi = max(hi, x);
        c.centre += x;
        const label g = groups.size() ? groups[perm[k]] : 0;
        c.gMin = min(c.gMin, g);
        c.gMax = max(c.gMax, g);
    }
    c.centre /= (end - begin);
    scalar r2 = 0;
    for (label k = begin; k < end; ++k)
    {
        r2 = max(r2, magSqr(pts[perm[k]] - c.centre));
    }
    c.radius = Foam::sqrt(r2);
    cells.push_back(c);

    const label n = end - begin;
    if (n <= leafSize || c.radius == 0)
    {
        return id;
    }

    // Halve the longest side of the bounding box, by count: the cell will
    // end in m = ceil(n/leafSize) leaves, of which the first m/2 go left,
    // so that all leaves hold n/m points (leafSize/2 < n/m <= leafSize)
    // whatever N is (an octree's leaf occupancy, and with it the cost per
    // point, jumps with N)
    const vector extent = hi - lo;
    const direction d =
        extent.x() >= extent.y() && extent.x() >= extent.z() ? 0
      : extent.y() >= extent.z() ? 1
      : 2;
    const label m = (n + leafSize - 1)/leafSize;
    const label nLeft = label(scalar(n)*(m/2)/m + 0.5);
    label* first = perm.begin() + begin;
    std::nth_element
    (
        first, first + nLeft, first + n,
        [&](const label i, const label j) { return pts[i][d] < pts[j][d]; }
    );
    const label c0 = split(begin, begin + nLeft, pts, groups, leafSize);
    const label c1 = split(begin + nLeft, end, pts, groups, leafSize);
    cells[id].nChild = 2;
    cells[id].child[0] = c0;
    cells[id].child[1] = c1;
    return id;
}


void Foam::bemFmm::tree::build
(
    const UList<point>& pts,
    const labelList& groups,
    const label leafSize
)
{
    cells.clear();
    cells.reserve(4*pts.size()/leafSize + 16);
    perm = identity(pts.size());
    if (pts.size())
    {
        split(0, pts.size(), pts, groups, leafSize);
    }
    x.resize(pts.size());
    y.resize(pts.size());
    z.resize(pts.size());
    g.resize(groups.size() == pts.size() ? pts.size() : 0);
    forAll(perm, k)
    {
        const point& p = pts[perm[k]];
        x[k] = p.x();
        y[k] = p.y();
        z[k] = p.z();
        if (g.size())
        {
            g[k] = groups[perm[k]];
        }
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::bemFmm::buildTables()
{
    // Numbering and components of the multi-indices as the templates above
    const label p = p_;
    ncDeg_.resize(p + 1);
    for (label q = 0; q <= p; ++q)
    {
        ncDeg_[q] = nCoef(q);
    }
    nc_ = nCoef(p);

    mi_.resize(nc_);
    for (label i = 0; i < nc_; ++i)
    {
        multiIndex& t = mi_[i];
        t.sign = degOf(i) % 2 ? -1 : 1;
        t.dim = 0;
        t.prev = 0;
        t.prev2 = 0;
        t.coef = 0;
        t.inv = 0;
        if (i == 0) continue;
        t.dim = dimOf(i);
        const label ni = compOf(i, t.dim);
        t.prev = lowerOf(i, 1);
        t.prev2 = ni > 1 ? lowerOf(i, 2) : 0;
        t.coef = ni - 1;
        t.inv = 1.0/ni;
    }

    // M2L: for each k, the index of n + k for |n| <= p - |k|
    m2lOff_.resize(nc_);
    m2lLen_.resize(nc_);
    m2lIdx_.clear();
    for (label k = 0; k < nc_; ++k)
    {
        m2lOff_[k] = m2lIdx_.size();
        m2lLen_[k] = nCoef(p - degOf(k));
        for (label i = 0; i < m2lLen_[k]; ++i)
        {
            m2lIdx_.push_back(sumIndex(k, i));
        }
    }

    // Shifts: (n, m, n - m) for m <= n componentwise
    shN_.clear();
    shM_.clear();
    shNM_.clear();
    for (label i = 0; i < nc_; ++i)
    {
        for (label j = 0; j < nc_; ++j)
        {
            if (aOf(j) <= aOf(i) && bOf(j) <= bOf(i) && cOf(j) <= cOf(i))
            {
                shN_.push_back(i);
                shM_.push_back(j);
                shNM_.push_back
                (
                    indexOf(aOf(i) - aOf(j), bOf(i) - bOf(j), cOf(i) - cOf(j))
                );
            }
        }
    }

    // L2P: k + e_d for |k| <= p - 1
    for (label d = 0; d < 3; ++d)
    {
        plus_[d].resize(nCoef(p - 1));
        for (label k = 0; k < nCoef(p - 1); ++k)
        {
            plus_[d][k] = indexOf
            (
                aOf(k) + (d == 0), bOf(k) + (d == 1), cOf(k) + (d == 2)
            );
        }
    }

    aux_.resize((p + 1)*nc_);
    w_.resize(nc_);
}


inline void Foam::bemFmm::monomials(const vector& d, scalar* w) const
{
    w[0] = 1;
    for (label i = 1; i < nc_; ++i)
    {
        const multiIndex& t = mi_[i];
        w[i] = w[t.prev]*d[t.dim]*t.inv;
    }
}


inline void Foam::bemFmm::derivatives(const vector& R, scalar* D) const
{
    // McMurchie-Davidson recurrence: R^(j)_n for |n| <= p - j, from
    // j = p (only n = 0) down to j = 0, where R^(0)_n = D^n (1/r)
    const label p = p_;
    const scalar ir2 = 1/magSqr(R);
    scalar f = Foam::sqrt(ir2);
    scalar* aux = aux_.data();
    for (label j = 0; j <= p; ++j)
    {
        aux[j*nc_] = f;                  // (-1)^j (2j - 1)!! r^-(2j+1)
        f *= -(2*j + 1)*ir2;
    }
    const multiIndex* mi = mi_.data();
    for (label j = p - 1; j >= 0; --j)
    {
        const scalar* up = aux + (j + 1)*nc_;
        scalar* cur = j ? aux + j*nc_ : D;
        cur[0] = aux[j*nc_];
        const label len = ncDeg_[p - j];
        for (label i = 1; i < len; ++i)
        {
            const multiIndex& t = mi[i];
            cur[i] = t.coef*up[t.prev2] + R[t.dim]*up[t.prev];
        }
    }
    if (p == 0)
    {
        D[0] = aux[0];
    }
}


void Foam::bemFmm::traverse
(
    const tree& T,
    const tree& S,
    const label a,
    const label b,
    const bool others,
    interactions& I
) const
{
    const cell& A = T.cells[a];
    const cell& B = S.cells[b];
    const scalar nA = A.end - A.begin, nB = B.end - B.begin;

    // Groups: nothing between cells of one and the same group; no
    // approximation where a target might see a source of its own group
    if (others && A.gMin == A.gMax && B.gMin == B.gMax && A.gMin == B.gMin)
    {
        return;
    }
    const bool overlap = others && A.gMin <= B.gMax && B.gMin <= A.gMax;

    if (I.mutual && a == b)
    {
        // Self-interaction of a cell: its children pairwise and each
        // child with itself
        if (A.nChild == 0)
        {
            (overlap ? I.p2pGroup : I.p2p).push_back({a, a});
            I.nDirect += nA*(nA - 1);
            return;
        }
        for (label i = 0; i < A.nChild; ++i)
        {
            for (label j = i; j < A.nChild; ++j)
            {
                traverse(T, S, A.child[i], A.child[j], others, I);
            }
        }
        return;
    }

    const scalar fac = I.mutual ? 2 : 1;
    if (!overlap && sqr(A.radius + B.radius) < sqr(theta_)*magSqr(A.centre - B.centre))
    {
        // Direct sum if cheaper (Dehnen 2002, Sec. 3.2)
        if (nA*nB < p2pMax_)
        {
            I.p2p.push_back({a, b});
            I.nDirect += fac*nA*nB;
            return;
        }
        I.m2l.push_back({a, b});
        I.nM2L += fac;
        return;
    }
    if (A.nChild == 0 && B.nChild == 0)
    {
        (overlap ? I.p2pGroup : I.p2p).push_back({a, b});
        I.nDirect += fac*nA*nB;
        return;
    }
    // Open the larger cell
    if (B.nChild == 0 || (A.nChild > 0 && A.radius >= B.radius))
    {
        for (label i = 0; i < A.nChild; ++i)
        {
            traverse(T, S, A.child[i], b, others, I);
        }
    }
    else
    {
        for (label i = 0; i < B.nChild; ++i)
        {
            traverse(T, S, a, B.child[i], others, I);
        }
    }
}


void Foam::bemFmm::upward(const UList<scalar>& q) const
{
    const tree& S = src_;
    const label nc = nc_;
    q_.resize(nSrc_);
    forAll(S.perm, k)
    {
        q_[k] = q[S.perm[k]];
    }
    M_.assign(S.cells.size()*nc, 0);
    Ms_.resize(S.cells.size()*nc);
    scalar* w = w_.data();
    // Children come after their parent: a reverse sweep is post-order
    for (label c = S.cells.size() - 1; c >= 0; --c)
    {
        const cell& C = S.cells[c];
        scalar* M = M_.data() + c*nc;
        if (C.nChild == 0)
        {
            // P2M
            for (label k = C.begin; k < C.end; ++k)
            {
                monomials
                (
                    vector(S.x[k], S.y[k], S.z[k]) - C.centre, w
                );
                const scalar qk = q_[k];
                for (label i = 0; i < nc; ++i)
                {
                    M[i] += qk*w[i];
                }
            }
        }
        else
        {
            // M2M: M_n += sum_{m <= n} M_m(child) s^(n-m)/(n-m)!
            const label ns = shN_.size();
            for (label o = 0; o < C.nChild; ++o)
            {
                const cell& ch = S.cells[C.child[o]];
                const scalar* Mc = M_.data() + C.child[o]*nc;
                monomials(ch.centre - C.centre, w);
                for (label t = 0; t < ns; ++t)
                {
                    M[shN_[t]] += Mc[shM_[t]]*w[shNM_[t]];
                }
            }
        }
        scalar* Ms = Ms_.data() + c*nc;
        for (label i = 0; i < nc; ++i)
        {
            Ms[i] = mi_[i].sign*M[i];
        }
    }
}


void Foam::bemFmm::multipoleToLocal
(
    const tree& T,
    const interactions& I
) const
{
    const label nc = nc_;
    // M2L: L_k(t) += sum_n (-1)^|n| M_n(s) D^(n+k)(z_t - z_s), and if
    // mutual L_k(s) += sum_n (-1)^|n| M_n(t) D^(n+k)(z_s - z_t), where
    // D^m(z_s - z_t) = (-1)^|m| D^m(z_t - z_s). Mutual and p <= 8: the
    // unrolled kernels; otherwise table-driven, for each n an update of the
    // contiguous L_k, |k| <= p - |n| (the row of n + k)
    std::vector<scalar> Dbuf(2*nc);
    scalar* __restrict__ D = Dbuf.data();
    scalar* __restrict__ Dm = D + nc;
    const label* idx = m2lIdx_.data();
    for (const std::pair<label, label>& pr : I.m2l)
    {
        const label t = pr.first, s = pr.second;
        const scalar* __restrict__ Mss = Ms_.data() + s*nc;
        scalar* __restrict__ Lt = L_.data() + t*nc;
        hasL_[t] = 1;
        if (I.mutual && p_ <= maxTemplateOrder)
        {
            hasL_[s] = 1;
            m2lMutualKernels[p_]
            (
                T.cells[t].centre - src_.cells[s].centre, Mss,
                M_.data() + t*nc, Lt, L_.data() + s*nc
            );
        }
        else if (I.mutual)
        {
            derivatives(T.cells[t].centre - src_.cells[s].centre, D);
            for (label m = 0; m < nc; ++m)
            {
                Dm[m] = mi_[m].sign*D[m];
            }
            const scalar* __restrict__ Mst = Ms_.data() + t*nc;
            scalar* __restrict__ Ls = L_.data() + s*nc;
            hasL_[s] = 1;
            for (label n = 0; n < nc; ++n)
            {
                const label* __restrict__ row = idx + m2lOff_[n];
                const label len = m2lLen_[n];
                const scalar a = Mss[n], b = Mst[n];
                for (label k = 0; k < len; ++k)
                {
                    Lt[k] += a*D[row[k]];
                    Ls[k] += b*Dm[row[k]];
                }
            }
        }
        else
        {
            derivatives(T.cells[t].centre - src_.cells[s].centre, D);
            for (label n = 0; n < nc; ++n)
            {
                const label* __restrict__ row = idx + m2lOff_[n];
                const label len = m2lLen_[n];
                const scalar a = Mss[n];
                for (label k = 0; k < len; ++k)
                {
                    Lt[k] += a*D[row[k]];
                }
            }
        }
    }
}


void Foam::bemFmm::particleToParticle
(
    const tree& T,
    const interactions& I
) const
{
    // P2P
    const tree& S = src_;
    const scalar* q = q_.data();
    for (const std::pair<label, label>& pr : I.p2p)
    {
        const cell& A = T.cells[pr.first];
        const cell& B = S.cells[pr.second];
        if (!I.mutual)
        {
            p2pOneWay
            (
                A.begin, A.end, B.begin, B.end, T.x.data(), T.y.data(),
                T.z.data(), S.x.data(), S.y.data(), S.z.data(), q,
                ex_.data(), ey_.data(), ez_.data(), ph_.data()
            );
        }
        else if (pr.first == pr.second)
        {
            p2pSelf
            (
                A.begin, A.end, S.x.data(), S.y.data(), S.z.data(), q,
                ex_.data(), ey_.data(), ez_.data(), ph_.data()
            );
        }
        else
        {
            p2pMutual
            (
                A.begin, A.end, B.begin, B.end, S.x.data(), S.y.data(),
                S.z.data(), q, ex_.data(), ey_.data(), ez_.data(),
                ph_.data()
            );
        }
    }
    for (const std::pair<label, label>& pr : I.p2pGroup)
    {
        // Only in evaluateOthers (mutual, T = S)
        const cell& A = T.cells[pr.first];
        const cell& B = S.cells[pr.second];
        const bool self = pr.first == pr.second;
        p2pGroups
        (
            A.begin, A.end, self ? -1 : B.begin, self ? -1 : B.end,
            S.x.data(), S.y.data(), S.z.data(), q, S.g.data(),
            ex_.data(), ey_.data(), ez_.data(), ph_.data()
        );
    }
}


void Foam::bemFmm::downward(const tree& T) const
{
    const label nc = nc_;
    // Downward: L2L to the children (parents come first), L2P at leaves
    scalar* w = w_.data();
    const label ns = shN_.size();
    const label nc1 = ncDeg_[p_ - 1];
    const label* px = plus_[0].data();
    const label* py = plus_[1].data();
    const label* pz = plus_[2].data();
    for (label c = 0; c < label(T.cells.size()); ++c)
    {
        if (!hasL_[c]) continue;
        const cell& C = T.cells[c];
        const scalar* L = L_.data() + c*nc;
        if (C.nChild)
        {
            // L2L: L_m(child) += sum_{n >= m} L_n s^(n-m)/(n-m)!
            for (label o = 0; o < C.nChild; ++o)
            {
                const label ch = C.child[o];
                scalar* Lc = L_.data() + ch*nc;
                monomials(T.cells[ch].centre - C.centre, w);
                for (label t = 0; t < ns; ++t)
                {
                    Lc[shM_[t]] += L[shN_[t]]*w[shNM_[t]];
                }
                hasL_[ch] = 1;
            }
        }
        else
        {
            // L2P: phi = sum_k L_k y^k/k!, E = -grad phi
            for (label k = C.begin; k < C.end; ++k)
            {
                monomials(vector(T.x[k], T.y[k], T.z[k]) - C.centre, w);
                scalar p = 0, fx = 0, fy = 0, fz = 0;
                for (label i = 0; i < nc1; ++i)
                {
                    p += L[i]*w[i];
                    fx += L[px[i]]*w[i];
                    fy += L[py[i]]*w[i];
                    fz += L[pz[i]]*w[i];
                }
                for (label i = nc1; i < nc; ++i)
                {
                    p += L[i]*w[i];
                }
                ph_[k] += p;
                ex_[k] -= fx;
                ey_[k] -= fy;
                ez_[k] -= fz;
            }
        }
    }
}


void Foam::bemFmm::apply(const tree& T, const interactions& I) const
{
    const label nc = nc_;
    const label nT = T.x.size();
    L_.assign(T.cells.size()*nc, 0);
    hasL_.assign(T.cells.size(), 0);
    ex_.assign(nT, 0);
    ey_.assign(nT, 0);
    ez_.assign(nT, 0);
    ph_.assign(nT, 0);
    nDirect_ = I.nDirect;
    nM2L_ = I.nM2L;

    multipoleToLocal(T, I);
    particleToParticle(T, I);
    downward(T);
}


void Foam::bemFmm::gather
(
    const tree& T,
    vectorField& E,
    scalarField* phi
) const
{
    const scalar c4pi = 1/(4*pi);
    forAll(T.perm, k)
    {
        const label t = T.perm[k];
        E[t] = c4pi*vector(ex_[k], ey_[k], ez_[k]);
        if (phi)
        {
            (*phi)[t] = c4pi*ph_[k];
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bemFmm::bemFmm
(
    const UList<point>& sources,
    const label order,
    const scalar theta,
    const label leafSize,
    const labelList& groups
)
:
    p_(order),
    theta_(theta),
    leafSize_(leafSize),
    nSrc_(sources.size()),
    p2pMax_(0),
    othersBuilt_(false),
    nc_(0),
    nDirect_(0),
    nM2L_(0)
{
    if (order < 1 || order > 10)
    {
        FatalErrorInFunction
            << "FMM expansion order p = " << order
            << " out of range [1, 10]" << exit(FatalError);
    }
    if (!(theta > 0 && theta < 1))
    {
        FatalErrorInFunction
            << "FMM opening parameter theta = " << theta
            << " out of range (0, 1)" << exit(FatalError);
    }
    if (leafSize < 1)
    {
        FatalErrorInFunction
            << "FMM leafSize = " << leafSize << " must be >= 1"
            << exit(FatalError);
    }
    if (groups.size() && groups.size() != sources.size())
    {
        FatalErrorInFunction
            << groups.size() << " groups for " << sources.size()
            << " sources" << exit(FatalError);
    }
    buildTables();
    // A mutual M2L costs about as much as C(p + 6, 6)/5 mutual point pairs
    // (measured: 0.16 us at p = 4, 0.33 us at p = 5; a pair 3.6 ns)
    p2pMax_ = 0.2*m2lIdx_.size();
    src_.build(sources, groups, leafSize);
    self_.mutual = true;
    others_.mutual = true;
    if (nSrc_)
    {
        traverse(src_, src_, 0, 0, false, self_);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bemFmm::evaluate
(
    const UList<scalar>& q,
    const UList<point>& targets,
    const bool sameSet,
    vectorField& E,
    scalarField* phi
) const
{
    E.setSize(targets.size());
    E = Zero;
    if (phi)
    {
        phi->setSize(targets.size());
        *phi = 0;
    }
    if (q.size() != nSrc_)
    {
        FatalErrorInFunction
            << q.size() << " charges for " << nSrc_ << " sources"
            << exit(FatalError);
    }
    if (sameSet && targets.size() != nSrc_)
    {
        FatalErrorInFunction
            << "sameSet with " << targets.size() << " targets for "
            << nSrc_ << " sources" << exit(FatalError);
    }
    if (nSrc_ == 0 || targets.empty())
    {
        return;
    }
    upward(q);
    if (sameSet)
    {
        apply(src_, self_);
        gather(src_, E, phi);
    }
    else
    {
        tree T;
        T.build(targets, labelList(), leafSize_);
        interactions I;
        I.mutual = false;
        traverse(T, src_, 0, 0, false, I);
        apply(T, I);
        gather(T, E, phi);
    }
}


void Foam::bemFmm::evaluateOthers
(
    const UList<scalar>& q,
    vectorField& E,
    scalarField* phi
) const
{
    if (label(src_.g.size()) != nSrc_)
    {
        FatalErrorInFunction
            << "evaluateOthers needs source groups" << exit(FatalError);
    }
    E.setSize(nSrc_);
    E = Zero;
    if (phi)
    {
        phi->setSize(nSrc_);
        *phi = 0;
    }
    if (nSrc_ == 0)
    {
        return;
    }
    if (!othersBuilt_)
    {
        traverse(src_, src_, 0, 0, true, others_);
        othersBuilt_ = true;
    }
    upward(q);
    apply(src_, others_);
    gather(src_, E, phi);
}


// ************************************************************************* //
