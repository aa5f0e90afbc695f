/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "latticeGreensFunction.H"
#include "mathematicalConstants.H"
#include "error.H"

#include <fftw3.h>
#include <cmath>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::latticeGreensFunction::latticeGreensFunction(const label M)
:
    M_(M),
    D_(),
    G0_(0)
{
    if (M < 1)
    {
        FatalErrorInFunction
            << "Lattice reach " << M << " must be >= 1" << exit(FatalError);
    }
    // The block |n_i| < B, Dirichlet values at |n_i| = B from the
    // asymptotic expansion (its next term, O(r^-5), is below 1e-9 there)
    const label B = M + 20;
    const label N = 2*B - 1;
    const label N3 = N*N*N;
    double* f = fftw_alloc_real(N3);
    const auto at = [&](const label i, const label j, const label k)
    {
        return (i*N + j)*N + k;
    };
    const auto asymptotic = [](const scalar x, const scalar y, const scalar z)
    {
        const scalar r2 = x*x + y*y + z*z;
        const scalar r = std::sqrt(r2);
        const scalar q4 = (x*x*x*x + y*y*y*y + z*z*z*z)/(r2*r2);
        return 1/(4*pi*r) + (5*q4 - 3)/(32*pi*r*r2);
    };
    for (label i = 0; i < N3; ++i)
    {
        f[i] = 0;
    }
    f[at(B - 1, B - 1, B - 1)] = 1;
    // The neighbours beyond each face of the block move to the right side
    for (label a = 0; a < N; ++a)
    {
        for (label b = 0; b < N; ++b)
        {
            const scalar pa = a - (B - 1);
            const scalar pb = b - (B - 1);
            for (const label s : {-1, 1})
            {
                const label edge = s < 0 ? 0 : N - 1;
                f[at(edge, a, b)] += asymptotic(s*B, pa, pb);
                f[at(a, edge, b)] += asymptotic(pa, s*B, pb);
                f[at(a, b, edge)] += asymptotic(pa, pb, s*B);
            }
        }
    }
    // RODFT00 twice is 2 (N + 1) times the identity per direction; the
    // eigenvalues of the Dirichlet 7-point operator are the sums of
    // 2 - 2 cos(pi (k + 1)/(N + 1)) over the three directions
    fftw_plan plan = fftw_plan_r2r_3d
    (
        N, N, N, f, f, FFTW_RODFT00, FFTW_RODFT00, FFTW_RODFT00,
        FFTW_ESTIMATE
    );
    fftw_execute(plan);
    List<scalar> lambda(N);
    forAll(lambda, k)
    {
        lambda[k] = 2 - 2*std::cos(pi*(k + 1)/(N + 1));
    }
    const scalar norm = std::pow(2.0*(N + 1), 3);
    for (label i = 0; i < N; ++i)
    {
        for (label j = 0; j < N; ++j)
        {
            for (label k = 0; k < N; ++k)
            {
                f[at(i, j, k)] /= norm*(lambda[i] + lambda[j] + lambda[k]);
            }
        }
    }
    fftw_execute(plan);
    fftw_destroy_plan(plan);

    const auto G = [&](const label a, const label b, const label c)
    {
        return f[at(B - 1 + a, B - 1 + b, B - 1 + c)];
    };
    G0_ = G(0, 0, 0);
    const label m = M + 1;
    D_.setSize(m*m*m);
    for (label a = 0; a <= M; ++a)
    {
        for (label b = 0; b <= M; ++b)
        {
            for (label c = 0; c <= M; ++c)
            {
                // G is even in each direction: G(-1) = G(1)
                D_[(a*m + b)*m + c] = vector
                (
                    -0.5*(G(a + 1, b, c) - G(std::abs(a - 1), b, c)),
                    -0.5*(G(a, b + 1, c) - G(a, std::abs(b - 1), c)),
                    -0.5*(G(a, b, c + 1) - G(a, b, std::abs(c - 1)))
                );
            }
        }
    }
    fftw_free(f);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::latticeGreensFunction::shape
(
    const vector& u,
    const scalar Rc,
    DynamicList<labelVector>& cells,
    DynamicList<scalar>& weights
)
{
    cells.clear();
    weights.clear();
    const labelVector lo
    (
        label(std::ceil(u.x() - Rc)),
        label(std::ceil(u.y() - Rc)),
        label(std::ceil(u.z() - Rc))
    );
    const labelVector hi
    (
        label(std::floor(u.x() + Rc)),
        label(std::floor(u.y() + Rc)),
        label(std::floor(u.z() + Rc))
    );
    scalar sum = 0;
    for (label i = lo.x(); i <= hi.x(); ++i)
    {
        for (label j = lo.y(); j <= hi.y(); ++j)
        {
            for (label k = lo.z(); k <= hi.z(); ++k)
            {
                const scalar r = mag(vector(i, j, k) - u);
                if (r < Rc)
                {
                    cells.append(labelVector(i, j, k));
                    weights.append(Rc - r);
                    sum += Rc - r;
                }
            }
        }
    }
    for (scalar& w : weights)
    {
        w /= sum;
    }
}


Foam::vector Foam::latticeGreensFunction::pairField
(
    const UList<labelVector>& cellsT,
    const UList<scalar>& wT,
    const UList<labelVector>& cellsS,
    const UList<scalar>& wS
) const
{
    vector E(Zero);
    forAll(cellsT, a)
    {
        vector Ea(Zero);
        forAll(cellsS, b)
        {
            const labelVector n(cellsT[a] - cellsS[b]);
            Ea += wS[b]*field(n.x(), n.y(), n.z());
        }
        E += wT[a]*Ea;
    }
    return E;
}


// ************************************************************************* //
