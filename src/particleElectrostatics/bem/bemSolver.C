/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bemSolver.H"
#include "simdClones.H"
#include "pairwiseCoulomb.H"
#include "mathematicalConstants.H"
#include "error.H"
#include "checkedEntry.H"

#include <Eigen/Dense>

#include <ctime>
#include <algorithm>
#include <cmath>
#include <unordered_map>

using Foam::constant::mathematical::pi;

struct Foam::bemSolver::luBlock
{
    Eigen::PartialPivLU<Eigen::MatrixXd> lu;
};

namespace
{

// Thread CPU time [s]: the solver is single-threaded, and CPU time is not
// inflated by other processes on a shared machine
double now()
{
    timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9*ts.tv_nsec;
}

// Direct sums between the patches i0..i1 of one particle and j0..j1 of
// another, both sides from one 1/r per pair (Newton's third law): eps0 E
// x 4 pi of the patch charges q and, withPotential, eps0 psi x 4 pi of
// the free sources w with their centre-of-charge shifts S (w S). Separate
// coordinate arrays and branch-free inner loops, so that they vectorise
template<bool withPotential>
SIMD_CLONES
void mutualDirectSums
(
    const Foam::label i0, const Foam::label i1,
    const Foam::label j0, const Foam::label j1,
    const Foam::scalar* X, const Foam::scalar* Y, const Foam::scalar* Z,
    const Foam::scalar* q, const Foam::scalar* w,
    const Foam::scalar* SX, const Foam::scalar* SY, const Foam::scalar* SZ,
    Foam::scalar* EX, Foam::scalar* EY, Foam::scalar* EZ, Foam::scalar* pot
)
{
    using Foam::scalar;
    for (Foam::label i = i0; i < i1; ++i)
    {
        const scalar xi = X[i], yi = Y[i], zi = Z[i], qi = q[i];
        scalar ex = 0, ey = 0, ez = 0, pt = 0;
        #pragma omp simd reduction(+:ex, ey, ez, pt)
        for (Foam::label j = j0; j < j1; ++j)
        {
            const scalar dx = xi - X[j];
            const scalar dy = yi - Y[j];
            const scalar dz = zi - Z[j];
            const scalar rInv = 1/std::sqrt(dx*dx + dy*dy + dz*dz);
            const scalar r3 = rInv*rInv*rInv;
            const scalar qr3 = q[j]*r3, qir3 = qi*r3;
            ex += qr3*dx;
            ey += qr3*dy;
            ez += qr3*dz;
            EX[j] -= qir3*dx;
            EY[j] -= qir3*dy;
            EZ[j] -= qir3*dz;
            if (withPotential)
            {
                pt += w[j]*rInv + (SX[j]*dx + SY[j]*dy + SZ[j]*dz)*r3;
                pot[j] +=
                    w[i]*rInv - (SX[i]*dx + SY[i]*dy + SZ[i]*dz)*r3;
            }
        }
        EX[i] += ex;
        EY[i] += ey;
        EZ[i] += ez;
        if (withPotential)
        {
            pot[i] += pt;
        }
    }
}

} // namespace


// * * * * * * * * * * * * * * * * Controls  * * * * * * * * * * * * * * * * //

Foam::bemSolverControls Foam::bemSolverControls::read
(
    const dictionary& dict
)
{
    auto atLeastOne = [](const label n) { return n >= 1; };
    auto nonNegative = [](const label n) { return n >= 0; };

    bemSolverControls c;
    c.tolerance = getCheckedOrDefault<scalar>
    (
        dict, "tolerance", c.tolerance,
        [](const scalar x) { return x > 0 && x < 1; },
        " (0, 1)", " (GMRES relative residual)"
    );
    c.maxIter = getCheckedOrDefault<label>
    (
        dict, "maxIter", c.maxIter, atLeastOne, ": >= 1",
        " (GMRES iteration limit)"
    );
    c.restart = getCheckedOrDefault<label>
    (
        dict, "restart", c.restart, atLeastOne, ": >= 1",
        " (GMRES restart length)"
    );
    c.theta = getCheckedOrDefault<scalar>
    (
        dict, "theta", c.theta,
        [](const scalar x) { return x > 0 && x <= 1; },
        " (0, 1]", " (treecode opening angle)"
    );
    c.order = getCheckedOrDefault<label>
    (
        dict, "order", c.order,
        [](const label n) { return n >= 0 && n <= 2; },
        " [0, 2]", " (treecode expansion order)"
    );
    dict.readIfPresent("leafSize", c.leafSize);
    c.fmmOrder = getCheckedOrDefault<label>
    (
        dict, "fmmOrder", c.fmmOrder,
        [](const label n) { return n >= 1 && n <= 10; },
        " [1, 10]", " (FMM expansion order)"
    );
    c.fmmTheta = getCheckedOrDefault<scalar>
    (
        dict, "fmmTheta", c.fmmTheta,
        [](const scalar x) { return x > 0 && x < 1; },
        " (0, 1)", " (FMM opening parameter)"
    );
    c.fmmLeafSize = getCheckedOrDefault<label>
    (
        dict, "fmmLeafSize", c.fmmLeafSize, atLeastOne, ": >= 1"
    );
    dict.readIfPresent("precondition", c.precondition);
    // Patch counts compared with a particle mesh's or the problem's size:
    // maxPreconditionerPatches 0 gives no particle a preconditioner block,
    // directOutputMax 0 evaluates the output by the fast sums at any size
    c.maxPreconditionerPatches = getCheckedOrDefault<label>
    (
        dict, "maxPreconditionerPatches", c.maxPreconditionerPatches,
        nonNegative,
        ": >= 0 (patches of the largest particle mesh that gets a"
        " preconditioner block)"
    );
    dict.readIfPresent("nearQuadrature", c.nearQuadrature);
    c.nearFactor = getCheckedOrDefault<scalar>
    (
        dict, "nearFactor", c.nearFactor,
        [](const scalar x) { return x >= 0 && std::isfinite(x); },
        ": it must be finite and >= 0 (0: no near quadrature)"
    );
    dict.readIfPresent("chargeConservation", c.chargeConservation);
    c.directOutputMax = getCheckedOrDefault<label>
    (
        dict, "directOutputMax", c.directOutputMax, nonNegative,
        ": >= 0 (patches up to which forces, torques and energy use direct"
        " sums)"
    );

    word w;
    if (dict.readIfPresent("matvec", w))
    {
        if (w == "direct") c.matvec = bemMatvecMethod::direct;
        else if (w == "treecode") c.matvec = bemMatvecMethod::treecode;
        else if (w == "fmm") c.matvec = bemMatvecMethod::fmm;
        else
        {
            FatalIOErrorInFunction(dict)
                << "matvec " << w << " unknown; allowed: direct treecode fmm"
                << exit(FatalIOError);
        }
    }
    if (dict.readIfPresent("selfTerm", w))
    {
        if (w == "zero") c.selfTerm = bemSelfTermModel::zero;
        else if (w == "curvature") c.selfTerm = bemSelfTermModel::curvature;
        else if (w == "gauss") c.selfTerm = bemSelfTermModel::gauss;
        else
        {
            FatalIOErrorInFunction(dict)
                << "selfTerm " << w << " unknown; allowed: gauss curvature zero"
                << exit(FatalIOError);
        }
    }
    return c;
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * * //

void Foam::bemSolver::nearCorrection
(
    const point& x,
    const pointField& qp,
    const scalarField& qw,
    const label j0,
    const point& xj,
    const scalar aj,
    vector& V,
    scalar& P
) const
{
    // Quadrature over the curved source patch minus its centroid rule
    const scalar c4pi = 1/(4*pi);
    V = Zero;
    P = 0;
    for (label q = 0; q < ellipsoidSurfaceMesh::nQuad; ++q)
    {
        const vector d = x - qp[j0 + q];
        const scalar r = mag(d);
        V += (qw[j0 + q]/(r*r*r))*d;
        P += qw[j0 + q]/r;
    }
    const vector d = x - xj;
    const scalar r = mag(d);
    V -= (aj/(r*r*r))*d;
    P -= aj/r;
    V *= c4pi;
    P *= c4pi;
}


Foam::scalar Foam::bemSolver::distanceBelow
(
    const label p,
    const point& y
) const
{
    // a_min (|S^-1 R^T (y - c)| - 1): the triangle inequality of the norm
    // |S^-1 .| (patch centres lie on the surface)
    const particle& pt = particles_[p];
    const vector& s = mesh(pt.shape).semiAxes();
    const vector yb = pt.R.T() & (y - pt.centre);
    return cmptMin(s)*
    (
        Foam::sqrt(sqr(yb.x()/s.x()) + sqr(yb.y()/s.y()) + sqr(yb.z()/s.z()))
      - 1
    );
}


void Foam::bemSolver::setPatches()
{
    // Every particle's patches in the world frame, their self terms and
    // near corrections within the body
    const label np = particles_.size();
    for (label p = 0; p < np; ++p)
    {
        const particle& pt = particles_[p];
        const shapeData& sd = *shapes_[pt.shape];
        const ellipsoidSurfaceMesh& m = *sd.mesh;
        for (label k = 0; k < m.size(); ++k)
        {
            const label i = offset_[p] + k;
            x_[i] = pt.centre + (pt.R & m.centres()[k]);
            n_[i] = pt.R & m.normals()[k];
            a_[i] = m.areas()[k];
            owner_[i] = p;
            kbar_[i] = 0.5*(pt.kappaP + kappa0_);
            dk_[i] = kappa0_ - pt.kappaP;
            selfK_[i] =
                ctrl_.selfTerm == selfTermModel::curvature
              ? m.meanCurvatures()[k]*m.selfJ()[k]/(8*pi)
              : ctrl_.selfTerm == selfTermModel::gauss
              ? sd.selfGauss[k]
              : 0;
            selfP_[i] = m.selfJ()[k]/(4*pi);
            if (ctrl_.nearQuadrature)
            {
                for (const nearEntry& e : sd.nearBody[k])
                {
                    nearEntry w = e;
                    w.j = offset_[p] + e.j;
                    w.V = pt.R & e.V;
                    near_[i].push_back(w);
                }
            }
        }
    }
}


void Foam::bemSolver::findNearPairs()
{
    // Near pairs between different particles: a source j of particle s is
    // near a target i of particle p when |x_i - x_j| < r_j = nearFactor
    // sqrt(a_j). Per pair of particles within reach, the candidates come
    // from a lower bound of the distance of a point y to ellipsoid p,
    // a_min (|S^-1 R^T (y - c)| - 1) (triangle inequality of the norm
    // |S^-1 .|; patch centres lie on the surface). Graded meshes make a
    // hash grid on the largest patch size quadratic in the patches.
    const label np = particles_.size();
    const label N = offset_[np];
    if (!(ctrl_.nearQuadrature && np > 1 && ctrl_.nearFactor > 0))
    {
        return;
    }
    scalarField rMaxOf(np, 0);
    for (label i = 0; i < N; ++i)
    {
        rMaxOf[owner_[i]] =
            max(rMaxOf[owner_[i]], ctrl_.nearFactor*Foam::sqrt(a_[i]));
    }
    // Round-off of the centres' projection onto the surface
    const scalar slack = 1 + 1e-9;
    pointField qpw(ellipsoidSurfaceMesh::nQuad);
    DynamicList<label> sources, targets;
    for (label s = 0; s < np; ++s)
    {
        const particle& ps = particles_[s];
        const ellipsoidSurfaceMesh& ms = mesh(ps.shape);
        for (label p = 0; p < np; ++p)
        {
            const particle& pp = particles_[p];
            if
            (
                p == s
             || mag(pp.centre - ps.centre)
             >= slack*
                (
                    cmptMax(mesh(pp.shape).semiAxes())
                  + cmptMax(ms.semiAxes()) + rMaxOf[s]
                )
            )
            {
                continue;
            }
            sources.clear();
            scalar rMax = 0;
            for (label j = offset_[s]; j < offset_[s + 1]; ++j)
            {
                const scalar rj = ctrl_.nearFactor*Foam::sqrt(a_[j]);
                if (distanceBelow(p, x_[j]) < slack*rj)
                {
                    sources.append(j);
                    rMax = max(rMax, rj);
                }
            }
            if (sources.empty())
            {
                continue;
            }
            targets.clear();
            for (label i = offset_[p]; i < offset_[p + 1]; ++i)
            {
                if (distanceBelow(s, x_[i]) < slack*rMax)
                {
                    targets.append(i);
                }
            }
            for (const label j : sources)
            {
                const label kj = j - offset_[s];
                const scalar rj = ctrl_.nearFactor*Foam::sqrt(a_[j]);
                bool haveQp = false;
                for (const label i : targets)
                {
                    if (magSqr(x_[i] - x_[j]) >= sqr(rj))
                    {
                        continue;
                    }
                    if (!haveQp)
                    {
                        for
                        (
                            label q = 0;
                            q < ellipsoidSurfaceMesh::nQuad;
                            ++q
                        )
                        {
                            qpw[q] = ps.centre
                              + (ps.R & ms.quadPoints()
                                    [ellipsoidSurfaceMesh::nQuad*kj + q]);
                        }
                        haveQp = true;
                    }
                    nearEntry e;
                    e.j = j;
                    scalarField qw
                    (
                        SubList<scalar>
                        (
                            ms.quadWeights(), ellipsoidSurfaceMesh::nQuad,
                            ellipsoidSurfaceMesh::nQuad*kj
                        )
                    );
                    nearCorrection
                    (
                        x_[i], qpw, qw, 0, x_[j], a_[j], e.V, e.P
                    );
                    near_[i].push_back(e);
                }
            }
        }
    }
}


void Foam::bemSolver::buildFastSum()
{
    // Fast sum
    fastSum_.reset();
    if (ctrl_.matvec == matvecMethod::treecode)
    {
        fastSum_.reset
        (
            new bemTreecode
            (
                x_, ctrl_.theta, ctrl_.order, ctrl_.leafSize, owner_
            )
        );
    }
    else if (ctrl_.matvec == matvecMethod::fmm)
    {
        fastSum_.reset
        (
            new bemFmm
            (
                x_, ctrl_.fmmOrder, ctrl_.fmmTheta, ctrl_.fmmLeafSize, owner_
            )
        );
    }
}


std::shared_ptr<Foam::bemSolver::luBlock>
Foam::bemSolver::factorisedBlock(const label p) const
{
    // Particle p's own block of the system (body frame), factorised
    const particle& pt = particles_[p];
    const shapeData& sd = *shapes_[pt.shape];
    const ellipsoidSurfaceMesh& m = *sd.mesh;
    const label n = m.size();
    const scalar kb = 0.5*(pt.kappaP + kappa0_);
    const scalar dkp = kappa0_ - pt.kappaP;
    Eigen::MatrixXd A(n, n);
    for (label i = 0; i < n; ++i)
    {
        const point& xi = m.centres()[i];
        const vector& ni = m.normals()[i];
        for (label j = 0; j < n; ++j)
        {
            if (i == j)
            {
                A(i, j) = kb + dkp*selfK_[offset_[p] + i];
                continue;
            }
            const vector d = xi - m.centres()[j];
            const scalar r = mag(d);
            A(i, j) = dkp*m.areas()[j]*(ni & d)/(4*pi*r*r*r);
        }
        if (ctrl_.nearQuadrature)
        {
            for (const nearEntry& e : sd.nearBody[i])
            {
                A(i, e.j) += dkp*(ni & e.V);
            }
        }
    }
    if (ctrl_.chargeConservation)
    {
        // Same rank-one flux correction as applyK, on
        // K = (A - kbar I)/dkappa
        scalar Ap = 0;
        for (label i = 0; i < n; ++i) Ap += m.areas()[i];
        for (label j = 0; j < n; ++j)
        {
            scalar flux = 0;
            for (label i = 0; i < n; ++i)
            {
                flux += m.areas()[i]
                  *(A(i, j) - (i == j ? kb : 0));
            }
            const scalar c =
                (flux - dkp*0.5*m.areas()[j])/Ap;
            for (label i = 0; i < n; ++i)
            {
                A(i, j) -= c;
            }
        }
    }
    auto block = std::make_shared<luBlock>();
    block->lu.compute(A);
    return block;
}


void Foam::bemSolver::buildPreconditioner()
{
    // Block preconditioner: once per (shape, kappaP, kappa0), body frame
    const label np = particles_.size();
    blockLU_.assign(np, nullptr);
    if (!ctrl_.precondition)
    {
        return;
    }
    for (label p = 0; p < np; ++p)
    {
        const particle& pt = particles_[p];
        shapeData& sd = *shapes_[pt.shape];
        if (sd.mesh->size() > ctrl_.maxPreconditionerPatches) continue;
        const std::pair<scalar, scalar> key(pt.kappaP, kappa0_);
        std::shared_ptr<luBlock> found;
        for (const auto& e : sd.lu)
        {
            if (e.first == key) found = e.second;
        }
        if (!found)
        {
            found = factorisedBlock(p);
            sd.lu.push_back({key, found});
        }
        blockLU_[p] = found;
    }
}


void Foam::bemSolver::assemble()
{
    const scalar t0 = now();
    const label np = particles_.size();
    for (const particle& p : particles_)
    {
        if (!shapes_[p.shape])
        {
            FatalErrorInFunction
                << "A particle's shape " << p.shape << " was released"
                << exit(FatalError);
        }
    }
    offset_.setSize(np + 1);
    offset_[0] = 0;
    for (label p = 0; p < np; ++p)
    {
        offset_[p + 1] = offset_[p] + mesh(particles_[p].shape).size();
    }
    const label N = offset_[np];
    x_.setSize(N);
    n_.setSize(N);
    a_.setSize(N);
    owner_.setSize(N);
    kbar_.setSize(N);
    dk_.setSize(N);
    selfK_.setSize(N);
    selfP_.setSize(N);
    near_.assign(N, std::vector<nearEntry>());

    for (auto& sd : shapes_)
    {
        if
        (
            sd
         && (
                sd->nearFactor != ctrl_.nearFactor
             || sd->nearQuad != ctrl_.nearQuadrature
            )
        )
        {
            buildNearBody(*sd);
        }
    }

    setPatches();
    findNearPairs();
    buildFastSum();
    buildPreconditioner();

    assembled_ = true;
    info_.setupTime = now() - t0;
}


void Foam::bemSolver::fieldOfAll
(
    const scalarField& q,
    vectorField& E,
    scalarField* phi
) const
{
    if (fastSum_)
    {
        fastSum_->evaluate(q, x_, true, E, phi);
    }
    else
    {
        bemTreecode::direct(x_, q, x_, true, E, phi);
    }
}


void Foam::bemSolver::applyK(const scalarField& x, scalarField& y) const
{
    const label N = x_.size();
    scalarField q(a_*x);
    vectorField E;
    fieldOfAll(q, E, nullptr);
    y.setSize(N);
    for (label i = 0; i < N; ++i)
    {
        vector Ei = E[i];
        for (const nearEntry& e : near_[i])
        {
            Ei += x[e.j]*e.V;
        }
        y[i] = (n_[i] & Ei) + selfK_[i]*x[i];
    }
    if (ctrl_.chargeConservation)
    {
        // Gauss: the flux of the particle's own charge through its surface
        // is half of it (principal value), that of all other charges zero
        for (label p = 0; p < label(particles_.size()); ++p)
        {
            scalar flux = 0, Q = 0, A = 0;
            for (label i = offset_[p]; i < offset_[p + 1]; ++i)
            {
                flux += a_[i]*y[i];
                Q += a_[i]*x[i];
                A += a_[i];
            }
            const scalar c = (flux - 0.5*Q)/A;
            for (label i = offset_[p]; i < offset_[p + 1]; ++i)
            {
                y[i] -= c;
            }
        }
    }
}


void Foam::bemSolver::applyA(const scalarField& x, scalarField& y) const
{
    applyK(x, y);
    y = kbar_*x + dk_*y;
}


void Foam::bemSolver::applyPrecond(const scalarField& x, scalarField& y) const
{
    y.setSize(x.size());
    for (label p = 0; p < label(particles_.size()); ++p)
    {
        const label b = offset_[p], n = offset_[p + 1] - offset_[p];
        if (blockLU_[p])
        {
            Eigen::Map<const Eigen::VectorXd> xv(x.cdata() + b, n);
            Eigen::Map<Eigen::VectorXd> yv(y.data() + b, n);
            yv = blockLU_[p]->lu.solve(xv);
        }
        else
        {
            for (label i = b; i < b + n; ++i)
            {
                y[i] = x[i]/(kbar_[i] + dk_[i]*selfK_[i]);
            }
        }
    }
}


bool Foam::bemSolver::isSphere(const label p) const
{
    return mesh(particles_[p].shape).sphere();
}


void Foam::bemSolver::freeSources
(
    const scalarField& sigmaF,
    scalarField& w,
    vectorField& shift
) const
{
    w = a_*sigmaF;
    shift.setSize(x_.size());
    shift = Zero;
    for (label s = 0; s < label(particles_.size()); ++s)
    {
        const particle& ps = particles_[s];
        if (!ps.uniformF)
        {
            continue;
        }
        const ellipsoidSurfaceMesh& ms = mesh(ps.shape);
        if (ms.sphere())
        {
            // A sphere: its exact monopole (addFreePotential)
            SubList<scalar>(w, ms.size(), offset_[s]) = 0;
            continue;
        }
        SubList<vector>(shift, ms.size(), offset_[s]) =
            ps.R & ms.chargeShifts();
    }
}


void Foam::bemSolver::addFreePotential
(
    const scalarField& sigmaF,
    const vectorField* shift,
    scalarField& phi
) const
{
    const bool pointKernelOnly = !shift;
    const label np = particles_.size();
    const scalar c4pi = 1/(4*pi);
    const label nQ = ellipsoidSurfaceMesh::nQuad;
    // Quadrature within this many patch sizes of a uniformly charged
    // ellipsoid's patch (the potential of a neighbour at gaps 0.02-0.5 of
    // its semi-axis within 1.2e-3 of a 16x finer mesh, as close as all
    // quadrature points)
    const scalar quadReach = 4;

    // Per source particle: its free charge and the reach of its
    // quadrature (5 % more: the centres of charge lie a little below the
    // surface)
    scalarField Qf(np, Zero), reach(np, Zero);
    for (label s = 0; s < np; ++s)
    {
        for (label j = offset_[s]; j < offset_[s + 1]; ++j)
        {
            Qf[s] += a_[j]*sigmaF[j];
        }
        reach[s] =
            1.05*quadReach*Foam::sqrt(max(mesh(particles_[s].shape).areas()));
    }

    for (label p = 0; p < np; ++p)
    {
        const particle& pt = particles_[p];
        const bool ownUnit = pt.uniformF && !pointKernelOnly;
        for (label i = offset_[p]; i < offset_[p + 1]; ++i)
        {
            scalar pot = 0;
            if (ownUnit)
            {
                pot += sigmaF[i]
                   *shapes_[pt.shape]->unitPotential[i - offset_[p]];
            }
            else
            {
                pot += selfP_[i]*sigmaF[i];
            }
            for (label s = 0; s < np && !pointKernelOnly; ++s)
            {
                const particle& ps = particles_[s];
                if (s == p || !ps.uniformF || Qf[s] == 0)
                {
                    continue;
                }
                if (isSphere(s))
                {
                    // Exact: Q/r outside, Q/R inside an overlap
                    pot += c4pi*Qf[s]/max
                    (
                        mag(x_[i] - ps.centre),
                        mesh(ps.shape).semiAxes().x()
                    );
                    continue;
                }
                if (distanceBelow(s, x_[i]) >= reach[s])
                {
                    continue;
                }
                // Patches within quadReach sizes: their quadrature points
                // in place of the centre-of-charge kernel of the direct sum
                const ellipsoidSurfaceMesh& ms = mesh(ps.shape);
                const vector xb = ps.R.T() & (x_[i] - ps.centre);
                const scalar sf = sigmaF[offset_[s]];
                for (label k = 0; k < ms.size(); ++k)
                {
                    const label j = offset_[s] + k;
                    const vector d = x_[i] - x_[j];
                    const scalar r2 = magSqr(d);
                    if (r2 > sqr(quadReach)*a_[j])
                    {
                        continue;
                    }
                    const vector& e = (*shift)[j];
                    const scalar rInv = 1/Foam::sqrt(r2);
                    scalar quad = 0;
                    for (label l = nQ*k; l < nQ*(k + 1); ++l)
                    {
                        quad +=
                            ms.quadWeights()[l]/mag(xb - ms.quadPoints()[l]);
                    }
                    pot += c4pi*sf*
                    (
                        quad - a_[j]*(rInv + (e & d)*rInv*rInv*rInv)
                    );
                }
            }
            for (const nearEntry& e : near_[i])
            {
                const label s = owner_[e.j];
                const bool pointKernel =
                    pointKernelOnly
                 || (s == p ? !ownUnit : !particles_[s].uniformF);
                if (pointKernel)
                {
                    pot += sigmaF[e.j]*e.P;
                }
            }
            forAll(pcX_, k)
            {
                pot += c4pi*pcQ_[k]/kappa0_/mag(x_[i] - pcX_[k]);
            }
            phi[i] += pot;
        }
    }
}


void Foam::bemSolver::directSums
(
    const scalarField& sigmaFall,
    const scalarField& q,
    const scalarField& qF,
    const bool withPotential,
    vectorField& E,
    scalarField& phi,
    vectorField& shift
) const
{
    const label N = x_.size();
    const label np = particles_.size();
    const scalar c4pi = 1/(4*pi);
    scalarField w;
    freeSources(sigmaFall, w, shift);
    scalarField X(N), Y(N), Z(N), SX(N), SY(N), SZ(N);
    for (label j = 0; j < N; ++j)
    {
        X[j] = x_[j].x();
        Y[j] = x_[j].y();
        Z[j] = x_[j].z();
        SX[j] = w[j]*shift[j].x();
        SY[j] = w[j]*shift[j].y();
        SZ[j] = w[j]*shift[j].z();
    }
    scalarField EX(N, Zero), EY(N, Zero), EZ(N, Zero), pot(N, Zero);
    for (label p = 0; p < np; ++p)
    {
        for (label s = p + 1; s < np; ++s)
        {
            (withPotential ? mutualDirectSums<true> : mutualDirectSums<false>)
            (
                offset_[p], offset_[p + 1], offset_[s], offset_[s + 1],
                X.cdata(), Y.cdata(), Z.cdata(), q.cdata(), w.cdata(),
                SX.cdata(), SY.cdata(), SZ.cdata(),
                EX.data(), EY.data(), EZ.data(), pot.data()
            );
        }
        if (!withPotential)
        {
            continue;
        }

        // Own patches by the point kernel, potential only: a non-uniform
        // free charge
        bool ownPoint = false;
        for (label i = offset_[p]; i < offset_[p + 1]; ++i)
        {
            ownPoint = ownPoint || sigmaFall[i] != 0;
        }
        ownPoint = ownPoint && !particles_[p].uniformF;
        for (label i = offset_[p]; i < offset_[p + 1] && ownPoint; ++i)
        {
            const scalar xi = X[i], yi = Y[i], zi = Z[i];
            scalar pt = 0;
            #pragma omp simd reduction(+:pt)
            for (label j = offset_[p]; j < offset_[p + 1]; ++j)
            {
                const scalar dx = xi - X[j];
                const scalar dy = yi - Y[j];
                const scalar dz = zi - Z[j];
                const scalar r2 = dx*dx + dy*dy + dz*dz;
                pt += (j == i ? 0 : qF[j]/std::sqrt(r2 + (j == i)));
            }
            pot[i] += pt;
        }
    }
    for (label i = 0; i < N; ++i)
    {
        E[i] = c4pi*vector(EX[i], EY[i], EZ[i]);
        phi[i] = c4pi*pot[i];
    }
}


void Foam::bemSolver::forcesAndEnergy
(
    const scalarField& q,
    const vectorField& E,
    const scalarField& phi
)
{
    // Forces and torques (Eq. 11) and the energy (Eq. 51, reciprocal)
    const label np = particles_.size();
    const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;
    force_.setSize(np);
    torque_.setSize(np);
    energy_ = 0;
    for (label p = 0; p < np; ++p)
    {
        vector F(Zero), M(Zero);
        for (label i = offset_[p]; i < offset_[p + 1]; ++i)
        {
            vector Ei = E[i]/eps0 + particleE_[p];
            if (Eext_)
            {
                Ei += Eext_(x_[i]);
            }
            const vector dF = kappa0_*q[i]*Ei;      // Eq. 11a
            F += dF;
            M += (x_[i] - particles_[p].centre) ^ dF; // Eq. 11b
            energy_ += 0.5*q[i]*phi[i]/eps0;   // Eq. 51 (reciprocal)
        }
        force_[p] = F;
        torque_[p] = M;
    }
}


void Foam::bemSolver::addPointChargeEnergy
(
    const scalarField& sigmaFall,
    const scalarField& qF,
    scalar& energy
) const
{
    const label N = x_.size();
    const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;
    const scalar c4pi = 1/(4*pi);
    // Free point charges: 1/2 q psi_f(x_k), near patches by quadrature
    forAll(pcX_, k)
    {
        scalar psi = 0;
        for (label j = 0; j < N; ++j)
        {
            const scalar r = mag(pcX_[k] - x_[j]);
            if
            (
                ctrl_.nearQuadrature
             && r < max(ctrl_.nearFactor, scalar(2))*Foam::sqrt(a_[j])
            )
            {
                const particle& pj = particles_[owner_[j]];
                const ellipsoidSurfaceMesh& mj = mesh(pj.shape);
                const label kj = j - offset_[owner_[j]];
                for (label qi = 0; qi < ellipsoidSurfaceMesh::nQuad; ++qi)
                {
                    const label l = ellipsoidSurfaceMesh::nQuad*kj + qi;
                    const point y = pj.centre + (pj.R & mj.quadPoints()[l]);
                    psi += sigmaFall[j]*mj.quadWeights()[l]/mag(pcX_[k] - y);
                }
            }
            else
            {
                psi += qF[j]/r;
            }
        }
        forAll(pcX_, l)
        {
            if (l != k)
            {
                psi += pcQ_[l]/kappa0_/mag(pcX_[k] - pcX_[l]);
            }
        }
        energy += 0.5*pcQ_[k]*c4pi*psi/eps0;
    }
}


void Foam::bemSolver::computeOutputs()
{
    const label N = x_.size();
    const label np = particles_.size();
    const scalar c4pi = 1/(4*pi);

    scalarField sigmaT(N), sigmaFall(N);
    for (label p = 0; p < np; ++p)
    {
        for (label k = 0; k < offset_[p + 1] - offset_[p]; ++k)
        {
            sigmaFall[offset_[p] + k] = particles_[p].sigmaF[k];
        }
    }
    sigmaT = sigmaFall + sigmaB_;
    const scalarField q(a_*sigmaT);
    const scalarField qF(a_*sigmaFall);

    // eps0 E of all other particles' surface charges at each patch, and
    // eps0 psi_f of the free charges by the point kernel: at the patches'
    // centres of charge (to first order in their shift from the patch
    // centres) for uniformly charged ellipsoids; spheres' exact monopoles,
    // own uniform densities, quadrature near the target and the point
    // charges are added by addFreePotential. Without the energy: E only
    vectorField E(N, Zero);
    scalarField phi(N, Zero);
    vectorField shift;
    const bool direct = !(fastSum_ && N > ctrl_.directOutputMax);
    if (!direct)
    {
        // Field of the other particles (exact exclusion), potential of all
        if (withEnergy_)
        {
            vectorField Eall;
            fastSum_->evaluate(qF, x_, true, Eall, &phi);
        }
        fastSum_->evaluateOthers(q, E, nullptr);
    }
    else
    {
        directSums(sigmaFall, q, qF, withEnergy_, E, phi, shift);
    }
    for (label i = 0; i < N; ++i)
    {
        for (const nearEntry& e : near_[i])
        {
            if (owner_[e.j] != owner_[i])
            {
                E[i] += sigmaT[e.j]*e.V;
            }
        }
        forAll(pcX_, k)
        {
            const vector d = x_[i] - pcX_[k];
            const scalar r = mag(d);
            E[i] += (c4pi*pcQ_[k]/kappa0_/(r*r*r))*d;
        }
    }
    if (withEnergy_)
    {
        for (const particle& pt : particles_)
        {
            shapeData& sd = *shapes_[pt.shape];
            if (direct && pt.uniformF && sd.unitPotential.empty())
            {
                sd.unitPotential = sd.mesh->unitPotential();
            }
        }
        addFreePotential(sigmaFall, direct ? &shift : nullptr, phi);
    }

    forcesAndEnergy(q, E, phi);

    // Free point charges: 1/2 q psi_f(x_k), near patches by quadrature
    if (withEnergy_)
    {
        addPointChargeEnergy(sigmaFall, qF, energy_);
    }
    energyValid_ = withEnergy_;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::bemSolver::bemSolver(const scalar kappa0, const controls& c)
:
    ctrl_(c),
    kappa0_(kappa0),
    assembled_(false),
    withEnergy_(true),
    energy_(0),
    energyValid_(false)
{
    if (!(kappa0 >= 1) || !std::isfinite(kappa0))
    {
        FatalErrorInFunction
            << "kappa0 = " << kappa0 << " out of range: finite and >= 1"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::bemSolver::buildNearBody(shapeData& sd) const
{
    const ellipsoidSurfaceMesh& m = *sd.mesh;
    const label n = m.size();
    sd.nearFactor = ctrl_.nearFactor;
    sd.lu.clear();
    sd.nearBody.assign(n, std::vector<nearEntry>());
    for (label i = 0; i < n; ++i)
    {
        for (label j = 0; j < n; ++j)
        {
            if (j == i) continue;
            const scalar rj = ctrl_.nearFactor*Foam::sqrt(m.areas()[j]);
            if (magSqr(m.centres()[i] - m.centres()[j]) >= sqr(rj)) continue;
            nearEntry e;
            e.j = j;
            nearCorrection
            (
                m.centres()[i], m.quadPoints(), m.quadWeights(),
                ellipsoidSurfaceMesh::nQuad*j, m.centres()[j], m.areas()[j],
                e.V, e.P
            );
            sd.nearBody[i].push_back(e);
        }
    }
    sd.nearQuad = ctrl_.nearQuadrature;

    // Gauss self term: K_jj = 1/2 - sum_{i != j} a_i K_ij/a_j
    sd.selfGauss.setSize(n);
    sd.selfGauss = 0;
    for (label i = 0; i < n; ++i)
    {
        const point& xi = m.centres()[i];
        const vector& ni = m.normals()[i];
        const scalar ai = m.areas()[i];
        for (label j = 0; j < n; ++j)
        {
            if (j == i) continue;
            const vector d = xi - m.centres()[j];
            const scalar r = mag(d);
            sd.selfGauss[j] += ai*m.areas()[j]*(ni & d)/(4*pi*r*r*r);
        }
        if (ctrl_.nearQuadrature)
        {
            for (const nearEntry& e : sd.nearBody[i])
            {
                sd.selfGauss[e.j] += ai*(ni & e.V);
            }
        }
    }
    sd.selfGauss = 0.5 - sd.selfGauss/m.areas();
}


Foam::bemSolver::controls& Foam::bemSolver::ctrl()
{
    // Controls may change the self blocks: refactorise on the next solve
    assembled_ = false;
    for (auto& sd : shapes_)
    {
        if (sd)
        {
            sd->lu.clear();
        }
    }
    return ctrl_;
}


Foam::label Foam::bemSolver::shape(const vector& semiAxes, const label nPatches)
{
    return shape(semiAxes, nPatches, vector(1, 0, 0), 1);
}


Foam::label Foam::bemSolver::shape
(
    const vector& semiAxes,
    const label nPatches,
    const vector& focus,
    const scalar lambda,
    const scalar beta
)
{
    const label nEven = nPatches + (nPatches % 2);
    const vector f = focus/max(mag(focus), VSMALL);
    for (label s = 0; s < label(shapes_.size()); ++s)
    {
        if (!shapes_[s])
        {
            continue;
        }
        const ellipsoidSurfaceMesh& m = *shapes_[s]->mesh;
        if
        (
            m.semiAxes() == semiAxes && m.size() == nEven
         && m.lambda() == lambda && (lambda == 1 || m.focus() == f)
         && m.beta() == beta
        )
        {
            return s;
        }
    }
    std::unique_ptr<shapeData> sd(new shapeData);
    if (lambda == 1)
    {
        sd->mesh.reset
        (
            new ellipsoidSurfaceMesh(semiAxes, nPatches, 40, beta)
        );
    }
    else
    {
        sd->mesh.reset
        (
            new ellipsoidSurfaceMesh
            (
                semiAxes, nPatches, focus, lambda, 40, beta
            )
        );
    }
    buildNearBody(*sd);
    shapes_.push_back(std::move(sd));
    return shapes_.size() - 1;
}


Foam::label Foam::bemSolver::addParticle
(
    const label shapeI,
    const point& centre,
    const tensor& R,
    const scalar kappaP,
    const scalar charge
)
{
    const ellipsoidSurfaceMesh& m = mesh(shapeI);
    return addParticle
    (
        shapeI, centre, R, kappaP, scalarField(m.size(), charge/sum(m.areas()))
    );
}


Foam::label Foam::bemSolver::addParticle
(
    const label shapeI,
    const point& centre,
    const tensor& R,
    const scalar kappaP,
    const scalarField& sigmaF
)
{
    if (shapeI < 0 || shapeI >= label(shapes_.size()) || !shapes_[shapeI])
    {
        FatalErrorInFunction << "shape index " << shapeI << " out of range"
            << " or released" << exit(FatalError);
    }
    if (!(kappaP >= 1) || !std::isfinite(kappaP))
    {
        FatalErrorInFunction
            << "kappaP = " << kappaP << " out of range: finite and >= 1"
            << exit(FatalError);
    }
    if (sigmaF.size() != mesh(shapeI).size())
    {
        FatalErrorInFunction
            << "sigmaF has " << sigmaF.size() << " values for "
            << mesh(shapeI).size() << " patches" << exit(FatalError);
    }
    if (mag(det(R) - 1) > 1e-6 || mag((R & R.T()) - tensor::I) > 1e-6)
    {
        FatalErrorInFunction
            << "rotation tensor " << R << " is not proper orthogonal"
            << exit(FatalError);
    }
    const bool uniform = sigmaF.empty() || min(sigmaF) == max(sigmaF);
    particles_.push_back({shapeI, centre, R, kappaP, sigmaF, uniform});
    particleE_.append(Zero);
    initialGuess_.append(scalarField());
    assembled_ = false;
    return particles_.size() - 1;
}


void Foam::bemSolver::setPose(const label i, const point& centre, const tensor& R)
{
    particles_[i].centre = centre;
    particles_[i].R = R;
    assembled_ = false;
}


void Foam::bemSolver::clearParticles()
{
    particles_.clear();
    particleE_.clear();
    initialGuess_.clear();
    pcX_.clear();
    pcQ_.clear();
    assembled_ = false;
}


void Foam::bemSolver::addPointCharge(const point& x, const scalar q)
{
    pcX_.append(x);
    pcQ_.append(q);
    assembled_ = false;
}


void Foam::bemSolver::setExternalField(const vector& E0)
{
    Eext_ = [E0](const point&) { return E0; };
}


void Foam::bemSolver::setExternalField(const fieldFunction& f)
{
    Eext_ = f;
}


void Foam::bemSolver::setParticleField(const label i, const vector& E)
{
    particleE_[i] = E;
}


void Foam::bemSolver::setInitialGuess(const label i, const scalarField& sigmaB)
{
    initialGuess_[i] = sigmaB;
}


Foam::tmp<Foam::scalarField> Foam::bemSolver::rightHandSide() const
{
    // Right-hand side of Eq. 8
    const label N = x_.size();
    const scalar eps0 = pairwiseCoulomb::vacuumPermittivity;
    const scalar c4pi = 1/(4*pi);

    scalarField sigmaF(N);
    for (label p = 0; p < label(particles_.size()); ++p)
    {
        for (label k = 0; k < offset_[p + 1] - offset_[p]; ++k)
        {
            sigmaF[offset_[p] + k] = particles_[p].sigmaF[k];
        }
    }
    scalarField Kf;
    applyK(sigmaF, Kf);
    tmp<scalarField> tb(new scalarField(N));
    scalarField& b = tb.ref();
    scalarField Eext(N);
    for (label i = 0; i < N; ++i)
    {
        scalar En = eps0*(n_[i] & particleE_[owner_[i]]);
        if (Eext_)
        {
            En += eps0*(n_[i] & Eext_(x_[i]));
        }
        forAll(pcX_, k)
        {
            const vector d = x_[i] - pcX_[k];
            const scalar r = mag(d);
            if
            (
                ctrl_.nearQuadrature
             && r < max(ctrl_.nearFactor, scalar(2))*Foam::sqrt(a_[i])
            )
            {
                // Flux through the patch / area
                const particle& pi_ = particles_[owner_[i]];
                const ellipsoidSurfaceMesh& mi = mesh(pi_.shape);
                const label ki = i - offset_[owner_[i]];
                scalar flux = 0;
                for (label q = 0; q < ellipsoidSurfaceMesh::nQuad; ++q)
                {
                    const label l = ellipsoidSurfaceMesh::nQuad*ki + q;
                    const point y = pi_.centre + (pi_.R & mi.quadPoints()[l]);
                    const vector ny = pi_.R
                      & ellipsoidSurfaceMesh::normal
                        (
                            mi.semiAxes(), mi.quadPoints()[l]
                        );
                    const vector dy = y - pcX_[k];
                    const scalar ry = mag(dy);
                    flux += mi.quadWeights()[l]*(ny & dy)/(ry*ry*ry);
                }
                En += c4pi*pcQ_[k]/kappa0_*flux/a_[i];
            }
            else
            {
                En += c4pi*pcQ_[k]/kappa0_*(n_[i] & d)/(r*r*r);
            }
        }
        Eext[i] = En;
    }
    if (ctrl_.chargeConservation)
    {
        // Sources outside a particle have zero net flux through it
        for (label p = 0; p < label(particles_.size()); ++p)
        {
            scalar flux = 0, A = 0;
            for (label i = offset_[p]; i < offset_[p + 1]; ++i)
            {
                flux += a_[i]*Eext[i];
                A += a_[i];
            }
            for (label i = offset_[p]; i < offset_[p + 1]; ++i)
            {
                Eext[i] -= flux/A;
            }
        }
    }
    for (label i = 0; i < N; ++i)
    {
        b[i] = (1 - kbar_[i])*sigmaF[i] - dk_[i]*(Kf[i] + Eext[i]);
    }
    return tb;
}


void Foam::bemSolver::gmres(const scalarField& b)
{
    const label N = x_.size();
    // Restarted GMRES, right preconditioning (Ruan, Eqs. 13-14)
    const scalar t0 = now();
    scalar tMv = 0;
    sigmaB_.setSize(N);
    sigmaB_ = 0;
    bool warm = false;
    for (label p = 0; p < label(particles_.size()); ++p)
    {
        if (initialGuess_[p].size() == offset_[p + 1] - offset_[p])
        {
            SubList<scalar>(sigmaB_, offset_[p + 1] - offset_[p], offset_[p]) =
                initialGuess_[p];
            warm = true;
        }
    }
    const scalar bnorm = Foam::sqrt(sum(sqr(b)));
    info_.iterations = 0;
    info_.residual = 0;
    const label m = ctrl_.restart;
    std::vector<scalarField> V;
    scalarField r(b), w(N), z(N);
    if (warm)
    {
        applyA(sigmaB_, w);
        r -= w;
    }
    scalar beta = Foam::sqrt(sum(sqr(r)));
    info_.converged = (bnorm == 0 || beta < ctrl_.tolerance*bnorm);
    info_.residual = bnorm > 0 ? beta/bnorm : 0;
    while (!info_.converged && info_.iterations < ctrl_.maxIter)
    {
        V.assign(1, scalarField(r/beta));
        Eigen::MatrixXd H = Eigen::MatrixXd::Zero(m + 1, m);
        Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1);
        Eigen::VectorXd cs(m), sn(m);
        g(0) = beta;
        label j = 0;
        for (; j < m && info_.iterations < ctrl_.maxIter; ++j)
        {
            applyPrecond(V[j], z);
            const scalar tm = now();
            applyA(z, w);
            tMv += now() - tm;
            ++info_.iterations;
            for (label i = 0; i <= j; ++i)
            {
                H(i, j) = sum(w*V[i]);
                w -= H(i, j)*V[i];
            }
            H(j + 1, j) = Foam::sqrt(sum(sqr(w)));
            V.push_back(scalarField(w/max(H(j + 1, j), VSMALL)));
            for (label i = 0; i < j; ++i)
            {
                const scalar t = cs(i)*H(i, j) + sn(i)*H(i + 1, j);
                H(i + 1, j) = -sn(i)*H(i, j) + cs(i)*H(i + 1, j);
                H(i, j) = t;
            }
            const scalar den = Foam::sqrt(sqr(H(j, j)) + sqr(H(j + 1, j)));
            cs(j) = H(j, j)/den;
            sn(j) = H(j + 1, j)/den;
            H(j, j) = den;
            H(j + 1, j) = 0;
            g(j + 1) = -sn(j)*g(j);
            g(j) = cs(j)*g(j);
            info_.residual = mag(g(j + 1))/bnorm;
            if (info_.residual < ctrl_.tolerance)
            {
                ++j;
                break;
            }
        }
        // Update x += M^-1 V y
        Eigen::VectorXd y =
            H.topLeftCorner(j, j).triangularView<Eigen::Upper>()
           .solve(g.head(j));
        scalarField u(N, Zero);
        for (label i = 0; i < j; ++i)
        {
            u += y(i)*V[i];
        }
        applyPrecond(u, z);
        sigmaB_ += z;
        // True residual
        applyA(sigmaB_, w);
        r = b - w;
        beta = Foam::sqrt(sum(sqr(r)));
        info_.residual = beta/bnorm;
        info_.converged = info_.residual < ctrl_.tolerance;
    }
    info_.solveTime = now() - t0;
    info_.matvecTime = tMv;
}


const Foam::bemSolver::solveInfo& Foam::bemSolver::solve()
{
    if (!assembled_)
    {
        assemble();
    }
    gmres(rightHandSide());
    if (!info_.converged)
    {
        WarningInFunction
            << "GMRES not converged: relative residual " << info_.residual
            << " after " << info_.iterations << " iterations (tolerance "
            << ctrl_.tolerance << ")" << endl;
    }

    computeOutputs();
    return info_;
}


const Foam::bemSolver::solveInfo& Foam::bemSolver::evaluate()
{
    if (!assembled_)
    {
        assemble();
    }
    sigmaB_.setSize(x_.size());
    for (label p = 0; p < label(particles_.size()); ++p)
    {
        const label n = offset_[p + 1] - offset_[p];
        if (initialGuess_[p].size() != n)
        {
            FatalErrorInFunction
                << "particle " << p << " has no bound charge of " << n
                << " patches to evaluate (setInitialGuess)"
                << exit(FatalError);
        }
        SubList<scalar>(sigmaB_, n, offset_[p]) = initialGuess_[p];
    }
    info_ = solveInfo();
    info_.converged = true;
    computeOutputs();
    return info_;
}


Foam::scalar Foam::bemSolver::energy() const
{
    if (!energyValid_)
    {
        FatalErrorInFunction
            << "no energy: the last solve() or evaluate() ran without it"
            << " (setWithEnergy(true) before it)" << exit(FatalError);
    }
    return energy_;
}


Foam::scalar Foam::bemSolver::matvecCpuTime(const label nRepeat) const
{
    if (!assembled_)
    {
        FatalErrorInFunction
            << "call solve() first" << exit(FatalError);
    }
    std::vector<scalar> t;
    scalarField y;
    for (label r = 0; r < max(nRepeat, label(1)); ++r)
    {
        const scalar t0 = now();
        applyA(sigmaB_, y);
        t.push_back(now() - t0);
    }
    std::sort(t.begin(), t.end());
    return t[t.size()/2];
}


Foam::SubList<Foam::scalar> Foam::bemSolver::sigmaB(const label i) const
{
    return SubList<scalar>(sigmaB_, offset_[i + 1] - offset_[i], offset_[i]);
}


Foam::SubList<Foam::point> Foam::bemSolver::centres(const label i) const
{
    return SubList<point>(x_, offset_[i + 1] - offset_[i], offset_[i]);
}


Foam::SubList<Foam::vector> Foam::bemSolver::normals(const label i) const
{
    return SubList<vector>(n_, offset_[i + 1] - offset_[i], offset_[i]);
}


Foam::pointField Foam::bemSolver::vertices(const label i) const
{
    const particle& p = particles_[i];
    const pointField& pb = mesh(p.shape).points();
    pointField pw(pb.size());
    forAll(pb, k)
    {
        pw[k] = p.centre + (p.R & pb[k]);
    }
    return pw;
}


Foam::scalar Foam::bemSolver::boundCharge(const label i) const
{
    scalar Q = 0;
    for (label k = offset_[i]; k < offset_[i + 1]; ++k)
    {
        Q += a_[k]*sigmaB_[k];
    }
    return Q;
}


Foam::vector Foam::bemSolver::boundDipole(const label i) const
{
    vector p(Zero);
    for (label k = offset_[i]; k < offset_[i + 1]; ++k)
    {
        p += (a_[k]*sigmaB_[k])*(x_[k] - particles_[i].centre);
    }
    return kappa0_*p;
}


void Foam::bemSolver::releaseShape(const label shapeI)
{
    for (const particle& p : particles_)
    {
        if (p.shape == shapeI)
        {
            FatalErrorInFunction
                << "Shape " << shapeI << " is in use by a particle"
                << exit(FatalError);
        }
    }
    shapes_[shapeI].reset();
}


Foam::scalar Foam::bemSolver::shapeBytes(const label shapeI) const
{
    const shapeData* sd = shapes_[shapeI].get();
    if (!sd)
    {
        return 0;
    }
    const label n = sd->mesh->size();
    // Mesh: centres, normals, areas, curvatures, 16 quadrature points and
    // weights per patch, vertices and faces (about 620 bytes per patch)
    scalar bytes =
        620.0*n + 8.0*sd->selfGauss.size() + 8.0*sd->unitPotential.size();
    for (const auto& near : sd->nearBody)
    {
        bytes += sizeof(nearEntry)*near.capacity() + sizeof(near);
    }
    // PartialPivLU: the n x n factors and the permutation
    bytes += sd->lu.size()*(8.0*n*n + 4.0*n);
    return bytes;
}


Foam::scalarField Foam::bemSolver::mediumCharges(const label i) const
{
    const scalarField& sigmaF = particles_[i].sigmaF;
    scalarField c(offset_[i + 1] - offset_[i]);
    forAll(c, k)
    {
        const label j = offset_[i] + k;
        c[k] = kappa0_*a_[j]*(sigmaF[k] + sigmaB_[j]);
    }
    return c;
}


Foam::pointMultipole Foam::bemSolver::multipole(const label i) const
{
    pointMultipole m;
    m.x0 = particles_[i].centre;
    const scalarField c(mediumCharges(i));
    forAll(c, k)
    {
        const vector d = x_[offset_[i] + k] - m.x0;
        m.q += c[k];
        m.p += c[k]*d;
        m.Q += c[k]*(3*sqr(d) - magSqr(d)*symmTensor::I);
    }
    return m;
}


// ************************************************************************* //
