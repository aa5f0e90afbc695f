/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "boxImages.H"
#include "ewaldSum.H"

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::boxImages::faceKind>
Foam::boxImages::faceKindNames
({
    { faceKind::grounded, "grounded" },
    { faceKind::insulating, "insulating" },
    { faceKind::periodic, "periodic" },
});


void Foam::boxImages::forces
(
    const UList<point>& x,
    const UList<scalar>& q,
    const point& origin,
    const vector& L,
    const FixedList<faceKind, 3>& kinds,
    const scalar epsilonR,
    const labelUList& targets,
    List<vector>& f,
    const scalar tolerance
)
{
    if (x.size() != q.size())
    {
        FatalErrorInFunction
            << "Positions (" << x.size() << ") and charges (" << q.size()
            << ") differ in size" << exit(FatalError);
    }
    for (direction d = 0; d < 3; ++d)
    {
        if (!(L[d] > 0))
        {
            FatalErrorInFunction
                << "Box edge " << d << " = " << L[d] << " must be > 0"
                << exit(FatalError);
        }
    }

    // Reflections: sign patterns over the walled axes (periodic axes are
    // never reflected); the first pattern (no reflection) is the charges
    vector cell(L);
    List<FixedList<scalar, 3>> patterns(1, FixedList<scalar, 3>(1));
    for (direction d = 0; d < 3; ++d)
    {
        if (kinds[d] == faceKind::periodic) continue;
        cell[d] = 2*L[d];
        const label n = patterns.size();
        patterns.setSize(2*n);
        for (label k = 0; k < n; ++k)
        {
            patterns[n + k] = patterns[k];
            patterns[n + k][d] = -1;
        }
    }

    const label N = x.size();
    List<point> xi(patterns.size()*N);
    List<scalar> qi(patterns.size()*N);
    forAll(patterns, k)
    {
        scalar parity = 1;
        for (direction d = 0; d < 3; ++d)
        {
            if (patterns[k][d] < 0)
            {
                parity *= (kinds[d] == faceKind::grounded ? -1 : 1);
            }
        }
        for (label i = 0; i < N; ++i)
        {
            const vector r = x[i] - origin;
            point& y = xi[k*N + i];
            for (direction d = 0; d < 3; ++d)
            {
                // Reflected across the lower wall, shifted by the period
                y[d] = patterns[k][d] < 0 ? cell[d] - r[d] : r[d];
            }
            qi[k*N + i] = parity*q[i];
        }
    }

    for (const label i : targets)
    {
        if (i < 0 || i >= N)
        {
            FatalErrorInFunction
                << "Target index " << i << " is out of range [0, " << N - 1
                << "]" << exit(FatalError);
        }
    }

    const ewaldSum ewald(cell, epsilonR, tolerance);
    ewald.forces(xi, qi, targets, f);
}


// ************************************************************************* //
