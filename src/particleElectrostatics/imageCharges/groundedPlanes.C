/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "groundedPlanes.H"
#include "error.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::groundedPlanes::groundedPlanes
(
    const UList<point>& points,
    const UList<vector>& normals,
    const scalar perpTol
)
:
    points_(points),
    normals_(normals),
    perpTol_(perpTol),
    pairs_(),
    triples_(),
    rightAngled_(true)
{
    if (points.size() != normals.size())
    {
        FatalErrorInFunction
            << points.size() << " points but " << normals.size()
            << " normals of grounded planes" << exit(FatalError);
    }
    if (!(perpTol_ > 0 && perpTol_ < 0.5))
    {
        FatalErrorInFunction
            << "Perpendicularity tolerance " << perpTol_
            << " must be in (0, 0.5)" << exit(FatalError);
    }

    forAll(normals_, i)
    {
        const scalar m = mag(normals_[i]);
        if (!(m > VSMALL) || !std::isfinite(m))
        {
            FatalErrorInFunction
                << "Grounded plane " << i << " through " << points_[i]
                << " has no normal (" << normals_[i] << ")"
                << exit(FatalError);
        }
        normals_[i] /= m;
    }

    // A plane listed twice would image every charge twice
    const label n = size();
    DynamicList<labelPair> pairs;
    for (label a = 0; a < n; ++a)
    {
        for (label b = a + 1; b < n; ++b)
        {
            const scalar c = normals_[a] & normals_[b];
            if (mag(c) < perpTol_)
            {
                pairs.append(labelPair(a, b));
            }
            else if (1 - mag(c) < perpTol_)
            {
                const scalar gap = mag((points_[b] - points_[a]) & normals_[a]);
                const scalar scale =
                    max(mag(points_[a]), mag(points_[b])) + VSMALL;
                if (gap < 1e-9*scale)
                {
                    FatalErrorInFunction
                        << "Grounded planes " << a << " and " << b
                        << " coincide (point " << points_[a] << ", normal "
                        << normals_[a] << ")" << exit(FatalError);
                }
            }
            else
            {
                // No composition: the images of two planes at an angle
                // other than 90 (or 0) degrees do not close
                rightAngled_ = false;
            }
        }
    }
    pairs_.transfer(pairs);

    DynamicList<FixedList<label, 3>> triples;
    for (const labelPair& ab : pairs_)
    {
        for (label c = ab.second() + 1; c < n; ++c)
        {
            if
            (
                mag(normals_[ab.first()] & normals_[c]) < perpTol_
             && mag(normals_[ab.second()] & normals_[c]) < perpTol_
            )
            {
                triples.append
                (
                    FixedList<label, 3>({ab.first(), ab.second(), c})
                );
            }
        }
    }
    triples_.transfer(triples);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::label Foam::groundedPlanes::appendImages
(
    const point& x,
    const scalar q,
    const scalar range,
    DynamicList<point>& xI,
    DynamicList<scalar>& qI
) const
{
    const label n0 = xI.size();

    // Planes this charge is in front of and closer than range
    auto near = [&](const label i)
    {
        const scalar d = distance(x, i);
        return d > 0 && d < range;
    };

    forAll(points_, a)
    {
        if (near(a))
        {
            xI.append(reflect(x, a));
            qI.append(-q);
        }
    }

    // Right-angle edges: the second reflection makes the balanced
    // quadrupole (Rasera 2022 section 2.4); perpendicular reflections
    // commute, so the order does not matter
    for (const labelPair& ab : pairs_)
    {
        if (near(ab.first()) && near(ab.second()))
        {
            xI.append(reflect(reflect(x, ab.first()), ab.second()));
            qI.append(q);
        }
    }

    // Right-angle corners: the octupole
    for (const FixedList<label, 3>& abc : triples_)
    {
        if (near(abc[0]) && near(abc[1]) && near(abc[2]))
        {
            xI.append(reflect(reflect(reflect(x, abc[0]), abc[1]), abc[2]));
            qI.append(-q);
        }
    }

    return xI.size() - n0;
}


void Foam::groundedPlanes::images
(
    const UList<point>& x,
    const UList<scalar>& q,
    const scalar range,
    pointField& xI,
    scalarField& qI,
    labelList* owner
) const
{
    DynamicList<point> xs(x.size());
    DynamicList<scalar> qs(x.size());
    DynamicList<label> os(owner ? x.size() : 0);
    forAll(x, i)
    {
        const label nI = appendImages(x[i], q[i], range, xs, qs);
        if (owner)
        {
            for (label k = 0; k < nI; ++k)
            {
                os.append(i);
            }
        }
    }
    xI.transfer(xs);
    qI.transfer(qs);
    if (owner)
    {
        owner->transfer(os);
    }
}


void Foam::groundedPlanes::addFieldsWithinCutoff
(
    const pairwiseCoulomb& coulomb,
    const UList<point>& xT,
    const UList<point>& xS,
    const UList<scalar>& qS,
    const scalar rCut,
    UList<vector>& ET,
    const label selfOffset,
    const scalar range
) const
{
    // Real sources first, then their images: the self index stays valid,
    // and a target feels its own images (the attraction to the wall)
    DynamicList<point> xAll(xS.size());
    DynamicList<scalar> qAll(qS.size());
    xAll.append(xS);
    qAll.append(qS);
    const scalar r = range > 0 ? range : rCut;
    forAll(xS, i)
    {
        appendImages(xS[i], qS[i], r, xAll, qAll);
    }

    coulomb.addFieldsWithinCutoff(xT, xAll, qAll, rCut, ET, selfOffset);
}


// ************************************************************************* //
