/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pseudoParticle.H"
#include "error.H"
#include "cutoffPairs.H"

#include <vector>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::pseudoParticle::pseudoParticle
(
    const vector& L,
    const scalar epsilonR,
    const label Nper,
    const label Nv,
    const label Ne
)
:
    periodicElectrostatics(L, epsilonR),
    Nper_(Nper),
    Nv_(Nv),
    Ne_(Ne)
{
    if (Nper < 1 || Nper > 20)
    {
        FatalErrorInFunction
            << "Nper = " << Nper << " is out of range [1, 20]"
            << exit(FatalError);
    }
    if (Nv < 0 || Nv > 100)
    {
        FatalErrorInFunction
            << "Nv = " << Nv << " is out of range [0, 100]"
            << exit(FatalError);
    }
    if (Ne < 0 || Ne > 1000)
    {
        FatalErrorInFunction
            << "Ne = " << Ne << " is out of range [0, 1000] (0: optimal)"
            << exit(FatalError);
    }
    if (Ne > 0 && 2*Nv + 1 > (2*Nper - 1)*Ne - 1)
    {
        FatalErrorInFunction
            << "Ne = " << Ne << ", Nv = " << Nv << ", Nper = " << Nper
            << " violate Boutsikakis 2023, Eq. (18):"
            << " 2 Nv + 1 <= (2 Nper - 1) Ne - 1" << exit(FatalError);
    }
}


Foam::pseudoParticle::pseudoParticle(const dictionary& dict)
:
    pseudoParticle
    (
        readBox(dict),
        readEpsilonR(dict),
        readLabel(dict, "Nper", 1, 1, 20),
        readLabel(dict, "Nv", 1, 0, 100),
        readLabel(dict, "Ne", 0, 0, 1000)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::pseudoParticle::optimalNe
(
    const label Np,
    const label Nv,
    const label Nper
)
{
    // App. A.2: dC/dNe = 0 <=> Ne^6 = Np (2Nv + 1)^3/(2Nper - 1)^3
    const scalar NeOpt =
        Foam::pow(scalar(Np), 1.0/6.0)
       *Foam::sqrt(scalar(2*Nv + 1)/scalar(2*Nper - 1));

    // Interval of App. A.2 / Eq. (18); the lower bound wins if empty
    const label lo = label(std::ceil(scalar(2*Nv + 2)/(2*Nper - 1) - 1e-12));
    const label hi = label(std::floor(std::cbrt(scalar(Np)) + 1e-9));
    return max(lo, min(hi, label(std::round(NeOpt))));
}


Foam::label Foam::pseudoParticle::Ne(const label Np) const
{
    return Ne_ > 0 ? Ne_ : optimalNe(Np, Nv_, Nper_);
}


void Foam::pseudoParticle::buildGrid
(
    const UList<point>& x,
    const UList<scalar>& q,
    cellGrid& g
) const
{
    const label N = x.size();
    const label ne = g.ne = Ne(N);
    const vector dx = g.dx = vector(L_.x()/ne, L_.y()/ne, L_.z()/ne);
    const label nCells = ne*ne*ne;
    std::vector<label>& cellOf = g.cellOf;
    std::vector<label>& start = g.start;
    std::vector<label>& order = g.order;
    std::vector<point>& xs = g.xs;
    std::vector<scalar>& qs = g.qs;
    std::vector<scalar>& Qk = g.Qk;
    std::vector<point>& xk = g.xk;
    std::vector<vector>& hk = g.hk;
    cellOf.resize(N);

    // Cell of each particle and particles sorted by cell
    std::vector<point> xw(N);
    for (label i = 0; i < N; ++i)
    {
        xw[i] = wrap(x[i]);
        label c[3];
        for (direction d = 0; d < 3; ++d)
        {
            c[d] = min(ne - 1, label(xw[i][d]/dx[d]));
        }
        cellOf[i] = c[0] + ne*(c[1] + ne*c[2]);
    }
    sortByBin(cellOf, nCells, start, order);
    xs.resize(N);
    qs.resize(N);
    for (label s = 0; s < N; ++s)
    {
        xs[s] = xw[order[s]];
        qs[s] = q[order[s]];
    }

    // Pseudo-particles (Eqs. 14-16) and their rectangles (Eqs. A.1-A.2):
    // centre xk, half-widths hk (to the nearest cell face)
    Qk.assign(nCells, 0);
    xk.resize(nCells);
    hk.resize(nCells);
    for (label c = 0; c < nCells; ++c)
    {
        const label ci[3] = {c % ne, (c/ne) % ne, c/(ne*ne)};
        const point xc
        (
            (ci[0] + 0.5)*dx.x(), (ci[1] + 0.5)*dx.y(), (ci[2] + 0.5)*dx.z()
        );
        scalar Q = 0, Qabs = 0;
        vector qx(Zero);
        for (label s = start[c]; s < start[c + 1]; ++s)
        {
            Q += qs[s];
            Qabs += mag(qs[s]);
            qx += qs[s]*xs[s];
        }
        Qk[c] = Q;
        point xe = (mag(Q) > 1e-12*Qabs && Qabs > 0) ? point(qx/Q) : xc;
        for (direction d = 0; d < 3; ++d)
        {
            const scalar lo = ci[d]*dx[d], hi = (ci[d] + 1)*dx[d];
            xe[d] = min(max(xe[d], lo), hi);
            hk[c][d] = max(scalar(0), 0.5*dx[d] - mag(xe[d] - xc[d]));
        }
        xk[c] = xe;
    }
}


void Foam::pseudoParticle::sumAt
(
    const cellGrid& g,
    const label s,
    vector& fp,
    scalar& qp
) const
{
    const label ne = g.ne;
    const vector& dx = g.dx;
    const std::vector<label>& start = g.start;
    const std::vector<label>& order = g.order;
    const std::vector<point>& xs = g.xs;
    const std::vector<scalar>& qs = g.qs;
    const std::vector<scalar>& Qk = g.Qk;
    const std::vector<point>& xk = g.xk;
    const std::vector<vector>& hk = g.hk;
    const label nImg = 2*Nper_ - 1;
    const vector half(0.5*nImg*L_.x(), 0.5*nImg*L_.y(), 0.5*nImg*L_.z());

    // Floor division for negative unwrapped cell indices
    auto fdiv = [](const label a, const label b)
    {
        return (a >= 0) ? a/b : -((-a + b - 1)/b);
    };

    const point& xp = xs[s];
    const label cp = g.cellOf[order[s]];
    const label cpi[3] = {cp % ne, (cp/ne) % ne, cp/(ne*ne)};
    const point lo = xp - half, hi = xp + half;
    label u0[3], u1[3];
    for (direction d = 0; d < 3; ++d)
    {
        u0[d] = label(std::floor(lo[d]/dx[d]));
        u1[d] = label(std::floor(hi[d]/dx[d]));
    }

    fp = Zero;
    qp = 0;

    for (label a2 = u0[2]; a2 <= u1[2]; ++a2)
    {
        const label w2 = fdiv(a2, ne);
        const label k2 = a2 - w2*ne;
        const scalar s2 = w2*L_.z();
        const bool near2 = mag(a2 - cpi[2]) <= Nv_;
        for (label a1 = u0[1]; a1 <= u1[1]; ++a1)
        {
            const label w1 = fdiv(a1, ne);
            const label k1 = a1 - w1*ne;
            const scalar s1 = w1*L_.y();
            const bool near1 = near2 && mag(a1 - cpi[1]) <= Nv_;
            for (label a0 = u0[0]; a0 <= u1[0]; ++a0)
            {
                const label w0 = fdiv(a0, ne);
                const label k0 = a0 - w0*ne;
                const vector shift(w0*L_.x(), s1, s2);
                const label c = k0 + ne*(k1 + ne*k2);

                if (near1 && mag(a0 - cpi[0]) <= Nv_)
                {
                    // Short range: direct with the particles (Eq. 17)
                    const bool own = (w0 == 0 && w1 == 0 && w2 == 0);
                    for (label t = start[c]; t < start[c + 1]; ++t)
                    {
                        if (own && t == s) continue;
                        const vector r = xp - (xs[t] + shift);
                        const scalar r2 = magSqr(r);
                        if (r2 == 0)
                        {
                            FatalErrorInFunction
                                << "Charges " << order[s] << " and "
                                << order[t] << " coincide at " << xp
                                << " (modulo the box)"
                                << exit(FatalError);
                        }
                        fp += (qs[t]/(r2*Foam::sqrt(r2)))*r;
                        qp += qs[t];
                    }
                    continue;
                }

                if (Qk[c] == 0) continue;

                // Long range: the pseudo-particle rectangle, cut by
                // the cube [lo, hi) (App. A.1, Fig. 11)
                const point xc = xk[c] + shift;
                const vector& h = hk[c];
                scalar frac = 1;
                point xSec = xc;
                for (direction d = 0; d < 3 && frac > 0; ++d)
                {
                    const scalar rl = xc[d] - h[d], rh = xc[d] + h[d];
                    if (rl >= lo[d] && rh <= hi[d]) continue;
                    if (h[d] == 0)
                    {
                        // Degenerate rectangle (single point)
                        if (xc[d] < lo[d] || xc[d] >= hi[d]) frac = 0;
                        continue;
                    }
                    const scalar sl = max(rl, lo[d]);
                    const scalar sh = min(rh, hi[d]);
                    if (sh <= sl)
                    {
                        frac = 0;
                        continue;
                    }
                    frac *= (sh - sl)/(rh - rl);
                    xSec[d] = 0.5*(sl + sh);
                }
                if (frac <= 0) continue;

                const scalar Q = frac*Qk[c];
                const vector r = xp - xSec;
                const scalar r2 = magSqr(r);
                if (r2 > 0)
                {
                    fp += (Q/(r2*Foam::sqrt(r2)))*r;
                }
                qp += Q;
            }
        }
    }
}


void Foam::pseudoParticle::evaluate
(
    const UList<point>& x,
    const UList<scalar>& q,
    UList<vector>* f,
    UList<scalar>* qSum
) const
{
    const label N = x.size();
    if (N == 0) return;

    cellGrid g;
    buildGrid(x, q, g);
    const label ne = g.ne;
    const label nImg = 2*Nper_ - 1;
    if (2*Nv_ + 1 > nImg*ne - 1)
    {
        FatalErrorInFunction
            << "Ne = " << ne << ", Nv = " << Nv_ << ", Nper = " << Nper_
            << " violate Boutsikakis 2023, Eq. (18):"
            << " 2 Nv + 1 <= (2 Nper - 1) Ne - 1" << exit(FatalError);
    }

    for (label s = 0; s < N; ++s)
    {
        vector fp;
        scalar qp;
        sumAt(g, s, fp, qp);
        const label i = g.order[s];
        if (f)
        {
            (*f)[i] = (k_*q[i])*fp;
        }
        if (qSum)
        {
            (*qSum)[i] = qp;
        }
    }
}


void Foam::pseudoParticle::compute
(
    const UList<point>& x,
    const UList<scalar>& q,
    List<vector>& f
) const
{
    checkInput(x, q);
    f.setSize(x.size());
    f = Zero;
    evaluate(x, q, &f, nullptr);
}


Foam::tmp<Foam::scalarField> Foam::pseudoParticle::interactingCharge
(
    const UList<point>& x,
    const UList<scalar>& q
) const
{
    checkInput(x, q);
    tmp<scalarField> tqs(new scalarField(x.size(), Zero));
    evaluate(x, q, nullptr, &tqs.ref());
    return tqs;
}


void Foam::pseudoParticle::writeInfo(Ostream& os) const
{
    periodicElectrostatics::writeInfo(os);
    os  << ", Nper = " << Nper_ << ", Nv = " << Nv_ << ", Ne = ";
    if (Ne_ > 0) os << Ne_; else os << "optimal";
}


// ************************************************************************* //
