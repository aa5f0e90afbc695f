/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "quasiPeriodicDirect.H"
#include "mathematicalConstants.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::quasiPeriodicDirect::quasiPeriodicDirect
(
    const vector& L,
    const scalar epsilonR,
    const label Nper,
    const bool removeDipole
)
:
    periodicElectrostatics(L, epsilonR),
    Nper_(Nper),
    removeDipole_(removeDipole)
{
    if (Nper < 1 || Nper > 20)
    {
        FatalErrorInFunction
            << "Number of periodic layers Nper = " << Nper
            << " is out of range [1, 20]" << exit(FatalError);
    }
}


Foam::quasiPeriodicDirect::quasiPeriodicDirect(const dictionary& dict)
:
    quasiPeriodicDirect
    (
        readBox(dict),
        readEpsilonR(dict),
        readLabel(dict, "Nper", 1, 1, 20),
        dict.getOrDefault<bool>("removeDipole", false)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::quasiPeriodicDirect::compute
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

    const label m = Nper_ - 1;

    if (m == 0)
    {
        // Nper = 1: the minimum image only (the paper's choice), written
        // out per component for speed (the O(N^2) loop dominates)
        // Positions wrapped into [0, L): |dx| < L, so the minimum image is
        // one conditional shift (branch-free; std::floor is a libm call
        // without SSE4.1)
        const scalar Lx = L_.x(), Ly = L_.y(), Lz = L_.z();
        const scalar hx = 0.5*Lx, hy = 0.5*Ly, hz = 0.5*Lz;
        List<point> xw(N);
        forAll(x, i)
        {
            xw[i] = wrap(x[i]);
        }
        for (label i = 0; i < N; ++i)
        {
            const scalar xi = xw[i].x(), yi = xw[i].y(), zi = xw[i].z();
            scalar fx = 0, fy = 0, fz = 0;
            for (label j = i + 1; j < N; ++j)
            {
                scalar dx = xi - xw[j].x();
                scalar dy = yi - xw[j].y();
                scalar dz = zi - xw[j].z();
                dx -= Lx*((dx > hx) - (dx < -hx));
                dy -= Ly*((dy > hy) - (dy < -hy));
                dz -= Lz*((dz > hz) - (dz < -hz));
                const scalar r2 = dx*dx + dy*dy + dz*dz;
                if (r2 == 0)
                {
                    FatalErrorInFunction
                        << "Charges " << i << " and " << j << " coincide at "
                        << x[i] << " (modulo the box)" << exit(FatalError);
                }
                const scalar g = 1/(r2*std::sqrt(r2));
                const scalar gj = q[j]*g, gi = q[i]*g;
                fx += gj*dx; fy += gj*dy; fz += gj*dz;
                f[j] -= vector(gi*dx, gi*dy, gi*dz);
            }
            f[i] += vector(fx, fy, fz);
        }
    }

    for (label i = 0; i < N && m > 0; ++i)
    {
        const point& xi = x[i];
        vector fi(Zero);
        for (label j = i + 1; j < N; ++j)
        {
            const vector d = minImage(xi - x[j]);
            vector fij(Zero);
            if (m == 0)
            {
                // Nper = 1: the minimum image only (the paper's choice)
                const scalar r2 = magSqr(d);
                if (r2 == 0)
                {
                    FatalErrorInFunction
                        << "Charges " << i << " and " << j << " coincide at "
                        << xi << " (modulo the box)" << exit(FatalError);
                }
                fij = d/(r2*Foam::sqrt(r2));
            }
            else
            {
                for (label n0 = -m; n0 <= m; ++n0)
                {
                    for (label n1 = -m; n1 <= m; ++n1)
                    {
                        for (label n2 = -m; n2 <= m; ++n2)
                        {
                            const vector r
                            (
                                d.x() + n0*L_.x(),
                                d.y() + n1*L_.y(),
                                d.z() + n2*L_.z()
                            );
                            const scalar r2 = magSqr(r);
                            if (r2 == 0)
                            {
                                FatalErrorInFunction
                                    << "Charges " << i << " and " << j
                                    << " coincide at " << xi
                                    << " (modulo the box)"
                                    << exit(FatalError);
                            }
                            fij += r/(r2*Foam::sqrt(r2));
                        }
                    }
                }
            }
            fi += q[j]*fij;
            f[j] -= q[i]*fij;
        }
        f[i] += fi;
    }

    forAll(f, i)
    {
        f[i] *= k_*q[i];
    }

    if (removeDipole_)
    {
        addMinImageDipole(x, q, f, -1);
    }
}


void Foam::quasiPeriodicDirect::addMinImageDipole
(
    const UList<point>& x,
    const UList<scalar>& q,
    UList<vector>& f,
    const scalar factor
) const
{
    const label N = x.size();
    const scalar V = L_.x()*L_.y()*L_.z();
    const scalar c = factor*4*constant::mathematical::pi*k_/(3*V);

    List<vector> s(N, Zero);
    for (label i = 0; i < N; ++i)
    {
        for (label j = i + 1; j < N; ++j)
        {
            const vector d = minImage(x[i] - x[j]);
            s[i] += q[j]*d;
            s[j] -= q[i]*d;
        }
    }
    forAll(f, i)
    {
        f[i] += (c*q[i])*s[i];
    }
}


void Foam::quasiPeriodicDirect::potentials
(
    const UList<point>& x,
    const UList<scalar>& q,
    scalarField& phi
) const
{
    checkInput(x, q);
    const label N = x.size();
    const label m = Nper_ - 1;
    phi.setSize(N);
    phi = 0;
    for (label i = 0; i < N; ++i)
    {
        for (label j = i + 1; j < N; ++j)
        {
            const vector d = minImage(x[i] - x[j]);
            scalar g = 0;
            for (label n0 = -m; n0 <= m; ++n0)
            {
                for (label n1 = -m; n1 <= m; ++n1)
                {
                    for (label n2 = -m; n2 <= m; ++n2)
                    {
                        const scalar r = mag
                        (
                            vector
                            (
                                d.x() + n0*L_.x(),
                                d.y() + n1*L_.y(),
                                d.z() + n2*L_.z()
                            )
                        );
                        if (r == 0)
                        {
                            FatalErrorInFunction
                                << "Charges " << i << " and " << j
                                << " coincide at " << x[i]
                                << " (modulo the box)" << exit(FatalError);
                        }
                        g += 1/r;
                    }
                }
            }
            phi[i] += q[j]*g;
            phi[j] += q[i]*g;
        }
    }
    phi *= k_;
}


void Foam::quasiPeriodicDirect::writeInfo(Ostream& os) const
{
    periodicElectrostatics::writeInfo(os);
    os  << ", Nper = " << Nper_ << ", removeDipole = " << removeDipole_;
}


// ************************************************************************* //
