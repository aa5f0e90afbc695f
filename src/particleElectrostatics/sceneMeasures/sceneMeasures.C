/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sceneMeasures.H"
#include "cutoffPairs.H"
#include "polyMesh.H"
#include "indexedOctree.H"
#include "treeDataFace.H"
#include "Random.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

Foam::scalarField Foam::sceneMeasures::nearestGaps
(
    const UList<point>& x,
    const UList<symmTensor>& Sinv,
    const UList<scalar>& aMin,
    const UList<scalar>& aMax,
    const UList<bool>& consider,
    const scalar maxGap
)
{
    const label n = x.size();
    scalarField gap(n, GREAT);
    if (n < 2)
    {
        return gap;
    }

    // A pair within maxGap smaller semi-axes has its centres closer than
    // the two largest semi-axes plus maxGap times the largest smallest one
    scalar aMaxMax = 0, aMinMax = 0;
    for (label i = 0; i < n; ++i)
    {
        aMaxMax = max(aMaxMax, aMax[i]);
        aMinMax = max(aMinMax, aMin[i]);
    }
    const scalar rCut = 2*aMaxMax + maxGap*aMinMax;
    if (!(rCut > 0))
    {
        return gap;
    }

    forPairsWithinCutoff
    (
        x, x, rCut, 0,
        [&](const label a, const label b, const vector& r, const scalar r2)
        {
            if (a >= b || (!consider[a] && !consider[b]) || !(r2 > 0))
            {
                return;
            }
            const scalar d = Foam::sqrt(r2);
            const vector u = r/d;
            const scalar g =
                d - Foam::sqrt(u & (Sinv[a] & u))
              - Foam::sqrt(u & (Sinv[b] & u));
            const scalar gn = g/min(aMin[a], aMin[b]);
            if (gn < maxGap)
            {
                if (consider[a])
                {
                    gap[a] = min(gap[a], gn);
                }
                if (consider[b])
                {
                    gap[b] = min(gap[b], gn);
                }
            }
        }
    );

    return gap;
}


Foam::scalarField Foam::sceneMeasures::distanceToFaces
(
    const polyMesh& mesh,
    const labelUList& faces,
    const UList<point>& x
)
{
    scalarField d(x.size(), GREAT);
    if (faces.empty() || x.empty())
    {
        return d;
    }

    // Bounding box of the faces' points, slightly extended and made
    // non-degenerate as OpenFOAM's own octree users do
    DynamicList<point> pts;
    for (const label facei : faces)
    {
        for (const label pointi : mesh.faces()[facei])
        {
            pts.append(mesh.points()[pointi]);
        }
    }
    Random rndGen(123456);
    const treeBoundBox bb
    (
        treeBoundBox(boundBox(pts, false)).extend(rndGen, 1e-4)
    );

    indexedOctree<treeDataFace> tree
    (
        treeDataFace(false, mesh, faces),
        bb,
        8,          // maxLevel
        10,         // leafSize
        3.0         // duplicity
    );

    const scalar span2 = magSqr(bb.span());
    forAll(x, i)
    {
        // Farther than the box: search out to the box's far corner
        const scalar r2 = span2 + magSqr(x[i] - bb.centre())*4;
        const pointIndexHit hit = tree.findNearest(x[i], r2);
        if (hit.hit())
        {
            d[i] = mag(hit.hitPoint() - x[i]);
        }
    }
    return d;
}


Foam::scalar Foam::sceneMeasures::percentile
(
    const UList<scalar>& values,
    const scalar p
)
{
    std::vector<scalar> v;
    v.reserve(values.size());
    for (const scalar s : values)
    {
        if (s < GREAT)
        {
            v.push_back(s);
        }
    }
    if (v.empty())
    {
        return GREAT;
    }
    const size_t k = min
    (
        v.size() - 1,
        size_t(std::max(0.0, std::ceil(p*v.size()) - 1))
    );
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[k];
}


// ************************************************************************* //
