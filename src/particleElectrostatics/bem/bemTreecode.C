/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bemTreecode.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <algorithm>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

Foam::label Foam::bemTreecode::build
(
    const label begin,
    const label end,
    const label depth
)
{
    const label id = nodes_.size();
    node blank;
    blank.centre = Zero;
    blank.radius = 0;
    blank.Q = 0;
    blank.P = Zero;
    blank.Qd = Zero;
    blank.gMin = labelMax;
    blank.gMax = labelMin;
    blank.begin = begin;
    blank.end = end;
    blank.nChild = 0;
    for (label o = 0; o < 8; ++o)
    {
        blank.child[o] = -1;
    }
    nodes_.push_back(blank);
    point boxCentre(Zero);
    vector extent(Zero);
    {
        node& nd = nodes_.back();
        nd.begin = begin;
        nd.end = end;
        nd.nChild = 0;
        point lo(GREAT, GREAT, GREAT), hi(-GREAT, -GREAT, -GREAT);
        for (label k = begin; k < end; ++k)
        {
            lo = min(lo, src_[perm_[k]]);
            hi = max(hi, src_[perm_[k]]);
        }
        // Expansion centre: mean of the points (tighter than the box
        // centre for points on curved surfaces); octants split at the box
        // centre below
        nd.centre = Zero;
        for (label k = begin; k < end; ++k)
        {
            nd.centre += src_[perm_[k]];
        }
        nd.centre /= (end - begin);
        boxCentre = 0.5*(lo + hi);
        extent = hi - lo;
        for (label k = begin; k < end; ++k)
        {
            const label g = group_.size() ? group_[perm_[k]] : 0;
            nd.gMin = min(nd.gMin, g);
            nd.gMax = max(nd.gMax, g);
        }
        scalar r2 = 0;
        for (label k = begin; k < end; ++k)
        {
            r2 = max(r2, magSqr(src_[perm_[k]] - nd.centre));
        }
        nd.radius = Foam::sqrt(r2);
    }

    if (end - begin <= leafSize_ || depth > 40 || nodes_[id].radius == 0)
    {
        return id;
    }

    // Partition into octants about the box centre, splitting only the
    // directions longer than half the longest one (cubic octants of an
    // elongated box, e.g. particles in a row, give slivers that are never
    // accepted as multipoles)
    const point c = boxCentre;
    const scalar emax = cmptMax(extent);
    const bool sx = extent.x() > 0.5*emax;
    const bool sy = extent.y() > 0.5*emax;
    const bool sz = extent.z() > 0.5*emax;
    label* first = perm_.begin() + begin;
    label* last = perm_.begin() + end;
    label* bounds[9];
    bounds[0] = first;
    bounds[8] = last;
    auto cx = [&](label i) { return !sx || src_[i].x() < c.x(); };
    auto cy = [&](label i) { return !sy || src_[i].y() < c.y(); };
    auto cz = [&](label i) { return !sz || src_[i].z() < c.z(); };
    bounds[4] = std::partition(first, last, cx);
    bounds[2] = std::partition(bounds[0], bounds[4], cy);
    bounds[6] = std::partition(bounds[4], bounds[8], cy);
    bounds[1] = std::partition(bounds[0], bounds[2], cz);
    bounds[3] = std::partition(bounds[2], bounds[4], cz);
    bounds[5] = std::partition(bounds[4], bounds[6], cz);
    bounds[7] = std::partition(bounds[6], bounds[8], cz);

    label children[8];
    label nc = 0;
    for (label o = 0; o < 8; ++o)
    {
        const label b = bounds[o] - perm_.begin();
        const label e = bounds[o + 1] - perm_.begin();
        if (e > b)
        {
            children[nc++] = build(b, e, depth + 1);
        }
    }
    node& nd = nodes_[id];
    nd.nChild = nc;
    for (label o = 0; o < nc; ++o)
    {
        nd.child[o] = children[o];
    }
    return id;
}


void Foam::bemTreecode::upward(const UList<scalar>& q) const
{
    qSorted_.setSize(perm_.size());
    forAll(perm_, k)
    {
        qSorted_[k] = q[perm_[k]];
    }
    // Children are created after their parent: a reverse sweep is a
    // post-order traversal
    for (label id = nodes_.size() - 1; id >= 0; --id)
    {
        node& nd = nodes_[id];
        nd.Q = 0;
        nd.P = Zero;
        nd.Qd = Zero;
        if (nd.nChild == 0)
        {
            for (label k = nd.begin; k < nd.end; ++k)
            {
                const vector d = srcSorted_[k] - nd.centre;
                const scalar qk = qSorted_[k];
                nd.Q += qk;
                nd.P += qk*d;
                nd.Qd += qk*(3*sqr(d) - magSqr(d)*symmTensor::I);
            }
        }
        else
        {
            for (label o = 0; o < nd.nChild; ++o)
            {
                const node& ch = nodes_[nd.child[o]];
                const vector d = ch.centre - nd.centre;
                nd.Q += ch.Q;
                nd.P += ch.P + ch.Q*d;
                // Shift of the traceless quadrupole by d
                nd.Qd += ch.Qd
                  + 3*twoSymm(d*ch.P)
                  + 3*ch.Q*sqr(d)
                  - (2*(d & ch.P) + ch.Q*magSqr(d))*symmTensor::I;
            }
        }
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bemTreecode::bemTreecode
(
    const UList<point>& sources,
    const scalar theta,
    const label order,
    const label leafSize,
    const labelList& groups
)
:
    src_(sources),
    group_(groups),
    perm_(identity(sources.size())),
    theta_(theta),
    order_(order),
    leafSize_(leafSize),
    nDirect_(0),
    nMultipole_(0)
{
    if (!(theta > 0 && theta <= 1))
    {
        FatalErrorInFunction
            << "treecode opening angle theta = " << theta
            << " out of range (0, 1]" << exit(FatalError);
    }
    if (order < 0 || order > 2)
    {
        FatalErrorInFunction
            << "treecode expansion order = " << order
            << " out of range [0, 2]" << exit(FatalError);
    }
    if (leafSize < 1)
    {
        FatalErrorInFunction
            << "treecode leafSize = " << leafSize << " must be >= 1"
            << exit(FatalError);
    }
    nodes_.reserve(4*sources.size()/max(leafSize, label(1)) + 16);
    if (sources.size())
    {
        build(0, sources.size(), 0);
    }
    srcSorted_.setSize(src_.size());
    forAll(perm_, k)
    {
        srcSorted_[k] = src_[perm_[k]];
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bemTreecode::evaluate
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
    if (nodes_.empty())
    {
        return;
    }
    upward(q);
    nDirect_ = 0;
    nMultipole_ = 0;

    const scalar c4pi = 1/(4*pi);
    const scalar theta2 = sqr(theta_);
    std::vector<label> stack;
    stack.reserve(256);

    forAll(targets, tt)
    {
        // Same set: visit the targets in tree order (neighbouring targets
        // traverse the same nodes: cache reuse)
        const label t =
            (sameSet && targets.size() == perm_.size()) ? perm_[tt] : tt;
        const point& x = targets[t];
        vector Et(Zero);
        scalar pt = 0;
        stack.clear();
        stack.push_back(0);
        while (!stack.empty())
        {
            const node& nd = nodes_[stack.back()];
            stack.pop_back();
            const vector R = x - nd.centre;
            const scalar r2 = magSqr(R);
            if (sqr(nd.radius) < theta2*r2)
            {
                nMultipole_ += 1;
                const scalar ir2 = 1/r2;
                const scalar ir = Foam::sqrt(ir2);
                const scalar ir3 = ir*ir2;
                Et += nd.Q*ir3*R;
                pt += nd.Q*ir;
                if (order_ >= 1)
                {
                    const scalar pR = nd.P & R;
                    Et += (3*pR*ir2*ir3)*R - ir3*nd.P;
                    pt += pR*ir3;
                }
                if (order_ >= 2)
                {
                    const vector QR = nd.Qd & R;
                    const scalar RQR = R & QR;
                    const scalar ir5 = ir3*ir2;
                    Et += (2.5*RQR*ir5*ir2)*R - ir5*QR;
                    pt += 0.5*RQR*ir5;
                }
            }
            else if (nd.nChild == 0)
            {
                nDirect_ += nd.end - nd.begin;
                for (label k = nd.begin; k < nd.end; ++k)
                {
                    if (sameSet && perm_[k] == t) continue;
                    const vector d = x - srcSorted_[k];
                    const scalar d2 = magSqr(d);
                    const scalar id = 1/Foam::sqrt(d2);
                    const scalar qk = qSorted_[k];
                    Et += (qk*id/d2)*d;
                    pt += qk*id;
                }
            }
            else
            {
                for (label o = 0; o < nd.nChild; ++o)
                {
                    stack.push_back(nd.child[o]);
                }
            }
        }
        E[t] = c4pi*Et;
        if (phi)
        {
            (*phi)[t] = c4pi*pt;
        }
    }
}


void Foam::bemTreecode::evaluateOthers
(
    const UList<scalar>& q,
    vectorField& E,
    scalarField* phi
) const
{
    if (group_.size() != src_.size())
    {
        FatalErrorInFunction
            << "evaluateOthers needs source groups" << exit(FatalError);
    }
    const UList<point>& targets = src_;
    const bool sameSet = true;
    E.setSize(targets.size());
    E = Zero;
    if (phi)
    {
        phi->setSize(targets.size());
        *phi = 0;
    }
    if (nodes_.empty())
    {
        return;
    }
    upward(q);
    nDirect_ = 0;
    nMultipole_ = 0;

    const scalar c4pi = 1/(4*pi);
    const scalar theta2 = sqr(theta_);
    std::vector<label> stack;
    stack.reserve(256);

    forAll(targets, t)
    {
        const point& x = targets[t];
        const label gt = group_[t];
        vector Et(Zero);
        scalar pt = 0;
        stack.clear();
        stack.push_back(0);
        while (!stack.empty())
        {
            const node& nd = nodes_[stack.back()];
            stack.pop_back();
            const vector R = x - nd.centre;
            const scalar r2 = magSqr(R);
            if (nd.gMin == gt && nd.gMax == gt)
            {
                continue;
            }
            const bool mixed = nd.gMin <= gt && gt <= nd.gMax;
            if (!mixed && sqr(nd.radius) < theta2*r2)
            {
                nMultipole_ += 1;
                const scalar ir2 = 1/r2;
                const scalar ir = Foam::sqrt(ir2);
                const scalar ir3 = ir*ir2;
                Et += nd.Q*ir3*R;
                pt += nd.Q*ir;
                if (order_ >= 1)
                {
                    const scalar pR = nd.P & R;
                    Et += (3*pR*ir2*ir3)*R - ir3*nd.P;
                    pt += pR*ir3;
                }
                if (order_ >= 2)
                {
                    const vector QR = nd.Qd & R;
                    const scalar RQR = R & QR;
                    const scalar ir5 = ir3*ir2;
                    Et += (2.5*RQR*ir5*ir2)*R - ir5*QR;
                    pt += 0.5*RQR*ir5;
                }
            }
            else if (nd.nChild == 0)
            {
                nDirect_ += nd.end - nd.begin;
                for (label k = nd.begin; k < nd.end; ++k)
                {
                    const label j = perm_[k];
                    if ((sameSet && j == t) || group_[j] == gt) continue;
                    const vector d = x - srcSorted_[k];
                    const scalar d2 = magSqr(d);
                    const scalar id = 1/Foam::sqrt(d2);
                    const scalar qk = qSorted_[k];
                    Et += (qk*id/d2)*d;
                    pt += qk*id;
                }
            }
            else
            {
                for (label o = 0; o < nd.nChild; ++o)
                {
                    stack.push_back(nd.child[o]);
                }
            }
        }
        E[t] = c4pi*Et;
        if (phi)
        {
            (*phi)[t] = c4pi*pt;
        }
    }
}


void Foam::bemTreecode::direct
(
    const UList<point>& sources,
    const UList<scalar>& q,
    const UList<point>& targets,
    const bool sameSet,
    vectorField& E,
    scalarField* phi
)
{
    E.setSize(targets.size());
    if (phi)
    {
        phi->setSize(targets.size());
    }
    const scalar c4pi = 1/(4*pi);
    const label ns = sources.size();
    forAll(targets, t)
    {
        const point x = targets[t];
        vector Et(Zero);
        scalar pt = 0;
        for (label j = 0; j < ns; ++j)
        {
            if (sameSet && j == t) continue;
            const vector d = x - sources[j];
            const scalar d2 = magSqr(d);
            const scalar id = 1/Foam::sqrt(d2);
            Et += (q[j]*id/d2)*d;
            pt += q[j]*id;
        }
        E[t] = c4pi*Et;
        if (phi)
        {
            (*phi)[t] = c4pi*pt;
        }
    }
}


// ************************************************************************* //
