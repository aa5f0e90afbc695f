/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "meshPoisson.H"
#include "cutoffPairs.H"
#include "fvm.H"
#include "fvc.H"
#include "fvMatrices.H"
#include "wallPolyPatch.H"
#include "cyclicPolyPatch.H"
#include "fixedValueFvPatchFields.H"
#include "zeroGradientFvPatchFields.H"
#include "mathematicalConstants.H"
#include "pairwiseCoulomb.H"
#include "emptyPolyPatch.H"
#include "processorPolyPatch.H"
#include "ListListOps.H"
#include "unitConversion.H"
#include "polyMeshTools.H"
#include "syncTools.H"
#include "PstreamBuffers.H"
#include "facePlanes.H"
#include "s2Shape.H"
#include "checkedEntry.H"

#include <Eigen/QR>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
    defineTypeNameAndDebug(meshPoisson, 0);
}

const Foam::Enum<Foam::meshPoisson::correctionType>
Foam::meshPoisson::correctionTypeNames
({
    { correctionType::shaped, "shaped" },
    { correctionType::cellCentroid, "cellCentroid" },
});


const Foam::Enum<Foam::meshPoisson::selfFieldSamplingType>
Foam::meshPoisson::selfFieldSamplingTypeNames
({
    { selfFieldSamplingType::points, "points" },
    { selfFieldSamplingType::charges, "charges" },
    { selfFieldSamplingType::automatic, "auto" },
});


namespace
{
    //- The entry key of dict, one of choices (default deflt), or a
    //  FatalIOError naming the entry and the allowed words
    template<class EnumType>
    EnumType readChoice
    (
        const Foam::dictionary& dict,
        const Foam::word& key,
        const Foam::Enum<EnumType>& choices,
        const EnumType deflt
    )
    {
        const Foam::word w(dict.lookupOrDefault<Foam::word>(key, choices[deflt]));
        if (!choices.found(w))
        {
            FatalIOErrorInFunction(dict)
                << "Entry " << key << " = " << w << " in "
                << dict.name().c_str() << " must be one of " << choices.names()
                << Foam::exit(Foam::FatalIOError);
        }
        return choices[w];
    }

    // Volt = kg m^2 s^-3 A^-1
    const Foam::dimensionSet dimPotential(1, 2, -3, 0, 0, -1, 0);
    const Foam::dimensionSet dimChargeDensity(0, -3, 1, 0, 0, 1, 0);
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::wordList Foam::meshPoisson::defaultPhiTypes(const fvMesh& mesh)
{
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    wordList types(pbm.size(), zeroGradientFvPatchScalarField::typeName);
    forAll(pbm, patchi)
    {
        if (isA<wallPolyPatch>(pbm[patchi]))
        {
            types[patchi] = fixedValueFvPatchScalarField::typeName;
        }
        else if (polyPatch::constraintType(pbm[patchi].type()))
        {
            types[patchi] = pbm[patchi].type();
        }
    }
    return types;
}


Foam::wordList Foam::meshPoisson::patchKinds(const fvMesh& mesh)
{
    const volScalarField Phi
    (
        IOobject
        (
            "Phi",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::NO_WRITE,
            false
        ),
        mesh,
        dimensionedScalar(dimPotential, Zero),
        defaultPhiTypes(mesh)
    );

    const polyBoundaryMesh& pbm = mesh.boundaryMesh();
    wordList kinds(pbm.size());
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        if (isA<processorPolyPatch>(pp))
        {
            // The last patches, and different on every processor
            kinds[patchi] = word::null;
            continue;
        }
        const fvPatchScalarField& pf = Phi.boundaryField()[patchi];
        // Every processor reduces, whatever its share of the patch
        const scalar maxPhi = gMax(mag(pf)());
        if (isA<emptyPolyPatch>(pp))
        {
            kinds[patchi] = word::null;
        }
        else if (isA<cyclicPolyPatch>(pp))
        {
            kinds[patchi] = "cyclic";
        }
        else if (pf.fixesValue())
        {
            kinds[patchi] = maxPhi > 0 ? "electrode" : "grounded";
        }
        else
        {
            kinds[patchi] = "insulating";
        }
    }
    return kinds;
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::meshPoisson::readRadius() const
{
    const word key
    (
        correction_ == correctionType::shaped ? "radius" : "rCut"
    );
    const scalar r = coeffs_.lookupOrDefault<scalar>(key, -1);
    if (!(r > 0) || !std::isfinite(r))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry " << key << " in " << coeffs_.name().c_str() << " is "
            << (coeffs_.found(key) ? "out of range" : "missing")
            << ": it must be given, finite and > 0 [m] ("
            << (correction_ == correctionType::shaped
                ? "radius of the deposited charge shape, a few cell sizes"
                : "near-field correction cutoff")
            << ")" << exit(FatalIOError);
    }
    return r;
}


Foam::scalar Foam::meshPoisson::readSelfFieldRadius() const
{
    return getCheckedOrDefault<scalar>
    (
        coeffs_, "selfFieldRadius", 3,
        [](const scalar D) { return D == 0 || (D >= 2 && D <= 10); },
        ": it must be 0 (keep each shape's field on itself) or in [2, 10]"
        " shape radii (the patch on which it is found and removed)"
    );
}


Foam::scalar Foam::meshPoisson::selfFieldPatchRadius() const
{
    // What is left of a removed self field is the mesh's response beyond
    // the patch, which falls with the patch's size in cells: with a shape
    // of 2 cells (radius 0.125 on the sphere of curvedCavities.py at
    // n = 13) 3 radii (6 cells) leave 2.5 % on a single charge in a weak
    // field and 8.5 % on a weak pair, 8 cells 0.94 and 3.0 %
    const scalar D = selfFieldRadius_*radius_;
    if (coeffs_.found("selfFieldRadius"))
    {
        return D;
    }
    const scalar meanCell = Foam::cbrt
    (
        gSum(mesh_.V().field())
       /returnReduce(mesh_.nCells(), sumOp<label>())
    );
    return max(D, 9*meanCell);
}


Foam::meshPoisson::selfFieldSamplingType
Foam::meshPoisson::readSelfFieldSampling() const
{
    return readChoice
    (
        coeffs_, "selfFieldSampling", selfFieldSamplingTypeNames,
        selfFieldSamplingType::automatic
    );
}


Foam::label Foam::meshPoisson::readNonOrthCorrectors() const
{
    const word key("nNonOrthogonalCorrectors");
    if (!coeffs_.found(key))
    {
        // Correctors until converged wherever the correction is not zero
        // to round-off
        return maxNonOrthogonality_ > 1e-6 ? 20 : 0;
    }
    return getChecked<label>
    (
        coeffs_, key,
        [](const label n) { return n >= 0; },
        ": it must be >= 0 (re-solves per evaluation with the Laplacian's"
        " non-orthogonal correction updated)"
    );
}


Foam::scalar Foam::meshPoisson::readNonOrthTolerance() const
{
    return getCheckedOrDefault<scalar>
    (
        coeffs_, "nonOrthogonalTolerance", 1e-6,
        [](const scalar tol) { return tol >= 0 && tol < 1; },
        ": it must be in [0, 1) (initial residual of the Phi solve below"
        " which no further non-orthogonal corrector runs)"
    );
}


Foam::scalar Foam::meshPoisson::maxNonOrthogonality() const
{
    // Cosine between each internal or coupled face's area vector and the
    // line joining its cells' centres (OpenFOAM's checkMesh measure)
    const scalar cosMin =
        gMin
        (
            polyMeshTools::faceOrthogonality
            (
                mesh_,
                mesh_.faceAreas(),
                mesh_.cellCentres()
            )
        );
    return Foam::acos(max(scalar(-1), min(scalar(1), cosMin)));
}


void Foam::meshPoisson::findPeriodicShifts()
{
    // One translation per cyclic pair
    periodicShifts_ = processorHalo::cyclicShifts(mesh_);
    if (periodicShifts_.size() > 3)
    {
        FatalIOErrorInFunction(coeffs_)
            << "The mesh has " << periodicShifts_.size() << " cyclic "
            << "translations; at most 3 are supported" << exit(FatalIOError);
    }
}


void Foam::meshPoisson::binCells()
{
    const vectorField& C = mesh_.C().primitiveField();
    binSize_ = radius_;
    binOrigin_ = Zero;
    nBins_ = Vector<label>(1, 1, 1);
    binCells_.clear();
    if (C.empty())
    {
        return;
    }
    point lo(C[0]), hi(C[0]);
    for (const point& c : C)
    {
        lo = min(lo, c);
        hi = max(hi, c);
    }
    // At most ~ one bin per cell
    while
    (
        (std::floor((hi.x() - lo.x())/binSize_) + 1)
       *(std::floor((hi.y() - lo.y())/binSize_) + 1)
       *(std::floor((hi.z() - lo.z())/binSize_) + 1) > C.size() + 64
    )
    {
        binSize_ *= 1.5;
    }
    binOrigin_ = lo;
    for (direction d = 0; d < 3; ++d)
    {
        nBins_[d] = label(std::floor((hi[d] - lo[d])/binSize_)) + 1;
    }
    labelList count(nBins_.x()*nBins_.y()*nBins_.z(), 0);
    labelList bin(C.size());
    forAll(C, celli)
    {
        label b = 0;
        for (direction d = 3; d-- > 0;)
        {
            const label i = min
            (
                max(label(std::floor((C[celli][d] - lo[d])/binSize_)), 0),
                nBins_[d] - 1
            );
            b = b*nBins_[d] + i;
        }
        bin[celli] = b;
        ++count[b];
    }
    binCells_.setSize(count.size());
    forAll(count, b)
    {
        binCells_[b].setSize(count[b]);
        count[b] = 0;
    }
    forAll(bin, celli)
    {
        binCells_[bin[celli]][count[bin[celli]]++] = celli;
    }
}


Foam::List<Foam::vector> Foam::meshPoisson::periodicTranslations() const
{
    return processorHalo::cyclicTranslations(mesh_);
}


void Foam::meshPoisson::addPeriodicCopies
(
    pointField& x,
    scalarField& q,
    labelList& origin,
    const scalar dist
)
{
    const label nReal = x.size();
    origin = identity(nReal);
    if (periodicShifts_.empty())
    {
        return;
    }

    const boundBox bb(mesh_.points(), false);
    DynamicList<point> gx(x);
    DynamicList<scalar> gq(q);
    DynamicList<label> go(origin);
    for (const vector& shift : periodicTranslations())
    {
        for (label i = 0; i < nReal; ++i)
        {
            const point y(x[i] + shift);
            const point yc(bb.nearest(y));
            if (magSqr(y - yc) < sqr(dist))
            {
                gx.append(y);
                gq.append(q[i]);
                go.append(i);
                addTransform(i, tensor::I, shift, 1);
            }
        }
    }
    x.transfer(gx);
    q.transfer(gq);
    origin.transfer(go);
}


void Foam::meshPoisson::cellsNear
(
    const point& y,
    const scalar R,
    DynamicList<label>& cells,
    DynamicList<scalar>& dist
) const
{
    cells.clear();
    dist.clear();
    const vectorField& C = mesh_.C().primitiveField();
    Vector<label> lo, hi;
    for (direction d = 0; d < 3; ++d)
    {
        lo[d] = max(label(std::floor((y[d] - R - binOrigin_[d])/binSize_)), 0);
        hi[d] = min
        (
            label(std::floor((y[d] + R - binOrigin_[d])/binSize_)),
            nBins_[d] - 1
        );
    }
    for (label k = lo.z(); k <= hi.z(); ++k)
    for (label j = lo.y(); j <= hi.y(); ++j)
    for (label i = lo.x(); i <= hi.x(); ++i)
    {
        for (const label celli : binCells_[(k*nBins_.y() + j)*nBins_.x() + i])
        {
            const scalar r2 = magSqr(C[celli] - y);
            if (r2 < R*R)
            {
                cells.append(celli);
                dist.append(std::sqrt(r2));
            }
        }
    }
}


void Foam::meshPoisson::shapeAt
(
    const point& y,
    DynamicList<label>& cells,
    DynamicList<scalar>& w
) const
{
    // S2 shape (Hockney & Eastwood section 8-3): rho(r) ~ (R - r) for
    // r < R, sampled at the cell centres
    cellsNear(y, radius_, cells, w);
    const scalarField& V = mesh_.V().field();
    forAll(cells, j)
    {
        w[j] = (radius_ - w[j])*V[cells[j]];
    }
}


void Foam::meshPoisson::setWallCoeffScales(const labelUList& fixedWallStart)
{
    // Fixed potentials on the wall's surface: the scale of each face's
    // coefficients from its surface height
    wallCoeffScale_.setSize(mesh_.boundaryMesh().size());
    forAll(fixedWallStart, patchi)
    {
        if (fixedWallStart[patchi] < 0)
        {
            continue;
        }
        const scalarField& deltaCoeffs = mesh_.boundary()[patchi].deltaCoeffs();
        scalarField& scale = wallCoeffScale_[patchi];
        scale.setSize(deltaCoeffs.size());
        forAll(scale, i)
        {
            // Planar walls (a fit's round-off) keep their coefficients; a
            // convex wall's surface lies inside the faces (s < 0)
            const scalar d = 1/deltaCoeffs[i];
            const scalar s = wallSurface_[fixedWallStart[patchi] + i][0];
            scale[i] = mag(s) < 1e-8*d ? 1 : d/(d + max(s, -0.5*d));
        }
    }
}


void Foam::meshPoisson::collectWallFaces()
{
    // This processor's wall faces (centre, outward unit normal,
    // circumradius, image sign) and their points
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const pointField& pts = mesh_.points();
    DynamicList<point> c, pointCentre, facePts;
    DynamicList<vector> n, pointNormal;
    DynamicList<scalar> r, sign;
    // Per patch fixing the potential: its first face's index here
    labelList fixedWallStart(pbm.size(), -1);
    forAll(pbm, patchi)
    {
        const polyPatch& pp = pbm[patchi];
        const fvPatchScalarField& pf = Phi_.boundaryField()[patchi];
        if (pp.coupled() || isA<emptyPolyPatch>(pp))
        {
            continue;
        }
        // Grounded or fixed potential: opposite image; insulating: equal
        const scalar sgn =
            pf.fixesValue() ? -1
          : isA<zeroGradientFvPatchScalarField>(pf) ? 1 : 0;
        if (sgn == 0)
        {
            continue;
        }
        if (sgn < 0)
        {
            fixedWallStart[patchi] = c.size();
        }
        forAll(pp, i)
        {
            const face& f = pp[i];
            const point fc(pp.faceCentres()[i]);
            const vector fn(normalised(pp.faceAreas()[i]));
            scalar rf = 0;
            for (const label pi : f)
            {
                rf = max(rf, mag(pts[pi] - fc));
                facePts.append(pts[pi]);
                pointCentre.append(fc);
                pointNormal.append(fn);
            }
            c.append(fc);
            n.append(fn);
            r.append(rf);
            sign.append(sgn);
        }
    }
    wallC_.transfer(c);
    wallN_.transfer(n);
    wallR_.transfer(r);
    wallSign_.transfer(sign);
    wallRMax_ = returnReduce(wallR_.size() ? max(wallR_) : 0, maxOp<scalar>());

    // The wall's surface over this processor's faces, from their points
    // and the other processors' within the fit's reach (a halo of the
    // points, each at its face's centre)
    const List<boundBox>& boxes = processorHalo::processorBoxes(mesh_);
    {
        const processorHalo pointHalo
        (
            boxes, pointCentre, 2.5*wallRMax_*(1 + 1e-9) + VSMALL
        );
        pointField points(facePts);
        vectorField normals(pointNormal);
        pointHalo.gather(points);
        pointHalo.gather(normals);
        fitWallSurfaces(pointHalo.points(), normals, points);
    }

    setWallCoeffScales(fixedWallStart);

    // The faces the images and the self fields' wall planes look up: those
    // within reach of this processor's box (a halo, with their fits): the
    // images of charges within 4R of the box in the walls within 2R of
    // them (addWallImages), the wall plane nearest to a self field's
    // centre (within 4R) within its patch radius and a cell's circumradius
    scalar cellRadius = 0;
    forAll(mesh_.cells(), celli)
    {
        for (const label pi : mesh_.cellPoints()[celli])
        {
            cellRadius = max(cellRadius, mag(pts[pi] - mesh_.C()[celli]));
        }
    }
    reduce(cellRadius, maxOp<scalar>());
    const scalar patchReach =
        selfFieldRadius_ > 0 ? selfFieldPatchRadius() + cellRadius : 0;
    // and the images of the lattice correction (addLatticeCorrection)
    const scalar latticeReach =
        lattice_.valid() ? 0.5*latticeImageReach() + wallRMax_ : 0;
    const processorHalo faceHalo
    (
        boxes,
        wallC_,
        (
            4*radius_
          + max(max(2*radius_ + wallRMax_, patchReach), latticeReach)
        )*(1 + 1e-9)
      + VSMALL
    );
    wallC_ = faceHalo.points();
    faceHalo.gather(wallN_);
    faceHalo.gather(wallR_);
    faceHalo.gather(wallSign_);
    faceHalo.gather(wallSurface_);
    nWallFaces_ = returnReduce(faceHalo.nLocal(), sumOp<label>());
}


void Foam::meshPoisson::placeOnWallSurface(fvScalarMatrix& M) const
{
    forAll(wallCoeffScale_, patchi)
    {
        const scalarField& scale = wallCoeffScale_[patchi];
        if (scale.size())
        {
            M.internalCoeffs()[patchi] *= scale;
            M.boundaryCoeffs()[patchi] *= scale;
        }
    }
}


void Foam::meshPoisson::wallFrame
(
    const label f,
    vector& eu,
    vector& ev
) const
{
    const vector& n = wallN_[f];
    eu = normalised(n ^ (mag(n.x()) < 0.9 ? vector(1, 0, 0) : vector(0, 1, 0)));
    ev = n ^ eu;
}


void Foam::meshPoisson::fitWallSurfaces
(
    const UList<point>& pointCentres,
    const UList<vector>& pointNormals,
    const UList<point>& points
)
{
    // The mesh's wall faces are chords of the user's wall (their points lie
    // on it, their centres inside a curved wall by ~h^2 kappa/8): a plane
    // image in a face's own plane would sit that much too close, a force
    // error of twice the ratio to the wall distance (8 % at 0.1 radii from
    // the wall of the sphere of curvedCavities.py, n = 13). The surface
    // through the points of the face and of the faces around it (centres
    // within 2.5 circumradii, one wall: normals within 45 degrees) gives
    // the tangent plane at a charge's foot instead. Least squares by
    // Eigen's column-pivoting QR; fewer than six independent points (a
    // lone face) keep the face's plane
    const scalar oneWallCos = Foam::cos(0.25*constant::mathematical::pi);
    wallSurface_.setSize(wallC_.size());
    // The points of the faces around each face (each point at its face's
    // centre, with its face's normal)
    List<DynamicList<label>> neighbours(wallC_.size());
    forPairsWithinCutoff
    (
        wallC_, pointCentres, 2.5*wallRMax_ + VSMALL, -1,
        [&](const label t, const label k, const vector& r, const scalar r2)
        {
            if
            (
                r2 < sqr(2.5*wallR_[t])
             && (wallN_[t] & pointNormals[k]) > oneWallCos
            )
            {
                neighbours[t].append(k);
            }
        }
    );
    forAll(wallC_, f)
    {
        FixedList<scalar, 6>& c = wallSurface_[f];
        c = Zero;
        vector eu, ev;
        wallFrame(f, eu, ev);
        const scalar L = wallR_[f];
        const label m = neighbours[f].size();
        if (m < 6 || !(L > 0))
        {
            continue;
        }
        // Scaled by the face's radius for conditioning
        Eigen::MatrixXd A(m, 6);
        Eigen::VectorXd h(m);
        label row = 0;
        for (const label k : neighbours[f])
        {
            const vector r((points[k] - wallC_[f])/L);
            const scalar u = r & eu;
            const scalar v = r & ev;
            A.row(row) << 1, u, v, u*u, u*v, v*v;
            h(row) = r & wallN_[f];
            ++row;
        }
        Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
        qr.setThreshold(1e-6);
        if (qr.rank() < 6)
        {
            continue;
        }
        const Eigen::VectorXd a(qr.solve(h));
        c[0] = a(0)*L;
        c[1] = a(1);
        c[2] = a(2);
        c[3] = a(3)/L;
        c[4] = a(4)/L;
        c[5] = a(5)/L;
    }
}


void Foam::meshPoisson::wallTangentPlane
(
    const label f,
    const point& y,
    point& p,
    vector& n
) const
{
    const FixedList<scalar, 6>& c = wallSurface_[f];
    vector eu, ev;
    wallFrame(f, eu, ev);
    p = y + ((wallC_[f] - y) & wallN_[f])*wallN_[f];
    n = wallN_[f];
    // The foot of y on the surface: two projections on its tangent plane
    // (the surface is within a face's sag of the face's plane). A point
    // beyond a concave wall's surface (inside its faces) keeps the face's
    // plane
    point pt(p);
    vector nt(n);
    for (label iter = 0; iter < 2; ++iter)
    {
        const vector r(pt - wallC_[f]);
        const scalar u = r & eu;
        const scalar v = r & ev;
        const scalar hu = c[1] + 2*c[3]*u + c[4]*v;
        const scalar hv = c[2] + c[4]*u + 2*c[5]*v;
        const point s
        (
            wallC_[f] + u*eu + v*ev
          + (c[0] + c[1]*u + c[2]*v + c[3]*u*u + c[4]*u*v + c[5]*v*v)
           *wallN_[f]
        );
        nt = normalised(wallN_[f] - hu*eu - hv*ev);
        pt = y + ((s - y) & nt)*nt;
    }
    if (((pt - y) & nt) > 0)
    {
        p = pt;
        n = nt;
    }
}


void Foam::meshPoisson::distinctWallPlanes
(
    const point& xi,
    const labelUList& faces,
    DynamicList<vector>& pn,
    DynamicList<scalar>& pd,
    DynamicList<scalar>& ps,
    DynamicList<label>& pf
) const
{
    const scalar oneWallCos = Foam::cos(0.25*constant::mathematical::pi);
    // Distinct planes (normal, distance, sign), nearest first, <= 3.
    // Faces whose normals are within 45 degrees are one wall, imaged
    // in its tangent plane at the foot of the charge on its nearest
    // face (the surface fitted there): the faces of a smooth wall near
    // a charge differ by the mesh's angular spacing, and one image per
    // face would count the wall several times; walls meeting at a
    // corner stay distinct
    pn.clear();
    pd.clear();
    ps.clear();
    pf.clear();
    for (const label f : faces)
    {
        const scalar d = (wallC_[f] - xi) & wallN_[f];
        bool known = false;
        forAll(pn, k)
        {
            if ((pn[k] & wallN_[f]) > oneWallCos)
            {
                if (d < pd[k])
                {
                    pn[k] = wallN_[f];
                    pd[k] = d;
                    ps[k] = wallSign_[f];
                    pf[k] = f;
                }
                known = true;
                break;
            }
        }
        if (!known)
        {
            pn.append(wallN_[f]);
            pd.append(d);
            ps.append(wallSign_[f]);
            pf.append(f);
        }
    }
}


template<class Visit>
void Foam::meshPoisson::forWallImages
(
    const UList<point>& x,
    const scalar reach,
    Visit&& visit
) const
{
    // The walls within reach of each point: the distinct planes of its
    // faces in range, each a wall's tangent plane at the point's foot
    // (not the face's chord plane: see fitWallSurfaces), the three
    // nearest
    if (wallC_.empty() || x.empty())
    {
        return;
    }
    const label n0 = x.size();
    DynamicList<labelPair> pairs;
    forPairsWithinCutoff
    (
        x, wallC_, reach + wallRMax_, -1,
        [&](const label t, const label f, const vector& r, const scalar)
        {
            // r = x - c_f; the wall lies at distance d along n_f
            const scalar d = -(r & wallN_[f]);
            if (d > 0 && d < reach && mag(r + d*wallN_[f]) <= 1.001*wallR_[f])
            {
                pairs.append(labelPair(t, f));
            }
        }
    );
    if (pairs.empty())
    {
        return;
    }
    // forPairsWithinCutoff visits the targets in order
    labelList start(n0 + 1, 0);
    for (const labelPair& tf : pairs)
    {
        ++start[tf.first() + 1];
    }
    for (label i = 0; i < n0; ++i)
    {
        start[i + 1] += start[i];
    }
    DynamicList<vector> pn;
    DynamicList<scalar> pd, ps;
    DynamicList<label> pf;
    for (label i = 0; i < n0; ++i)
    {
        if (start[i + 1] == start[i])
        {
            continue;
        }
        DynamicList<label> faces(start[i + 1] - start[i]);
        for (label j = start[i]; j < start[i + 1]; ++j)
        {
            faces.append(pairs[j].second());
        }
        distinctWallPlanes(x[i], faces, pn, pd, ps, pf);
        if (pn.empty())
        {
            continue;
        }
        forAll(pn, k)
        {
            point p;
            wallTangentPlane(pf[k], x[i], p, pn[k]);
            pd[k] = (p - x[i]) & pn[k];
        }
        labelList order;
        sortedOrder(pd, order);
        const label np = min(order.size(), label(3));

        // Subsets of the planes: single reflections always; compositions
        // only of mutually perpendicular planes (exact there)
        for (label mask = 1; mask < (1 << np); ++mask)
        {
            // y = T x + b from the reflections y -> (I - 2 n n) y + 2 (p.n) n
            tensor T(tensor::I);
            vector b(Zero);
            scalar sgn = 1;
            bool ok = true;
            for (label a = 0; a < np && ok; ++a)
            {
                if (!(mask & (1 << a)))
                {
                    continue;
                }
                for (label c = a + 1; c < np; ++c)
                {
                    if
                    (
                        (mask & (1 << c))
                     && mag(pn[order[a]] & pn[order[c]]) > 1e-6
                    )
                    {
                        ok = false;
                    }
                }
                const label k = order[a];
                // The plane through p = x + d n
                const point p(x[i] + pd[k]*pn[k]);
                const tensor H(tensor::I - 2*sqr(pn[k]));
                T = H & T;
                b = (H & b) + 2*(p & pn[k])*pn[k];
                sgn *= ps[k];
            }
            if (ok)
            {
                visit(i, T, b, sgn);
            }
        }
    }
}


void Foam::meshPoisson::addWallImages
(
    pointField& x,
    scalarField& q,
    labelList& origin
)
{
    // The images of each shape in the walls within 2R (method of
    // images for a plane; for two or three perpendicular planes, an edge or
    // a corner, also the images of the images). Deposited together, a
    // shape cut by the walls and its images solve the wall problem exactly
    // for planar walls, and the near-field correction stays compact: the
    // same free-space kernel around every image
    if (wallC_.empty())
    {
        return;
    }
    const label n0 = x.size();
    const scalar R = radius_;
    // Only charges within 4R of this processor's cells matter here (a
    // charge within 2R of a wall has its image within 4R, and the image's
    // correction reaches 2R)
    DynamicList<label> here;
    DynamicList<point> xHere;
    for (label i = 0; i < n0; ++i)
    {
        if (magSqr(localBb_.nearest(x[i]) - x[i]) < sqr(4*R))
        {
            here.append(i);
            xHere.append(x[i]);
        }
    }

    DynamicList<point> gx(x);
    DynamicList<scalar> gq(q);
    DynamicList<label> go(origin);
    forWallImages
    (
        xHere, 2*R,
        [&](const label h, const tensor& T, const vector& b, const scalar sgn)
        {
            const label i = here[h];
            gx.append((T & x[i]) + b);
            gq.append(sgn*q[i]);
            go.append(origin[i]);
            addTransform(i, T, b, sgn);
        }
    );
    x.transfer(gx);
    q.transfer(gq);
    origin.transfer(go);
}


void Foam::meshPoisson::shapeWeights
(
    const UList<point>& x,
    const labelUList& origin,
    const label nReal
)
{
    const scalar R = radius_;

    // One search per source: the local cells within R and their weights
    // (R - r) V, summed per charge over its copies, images and all
    // processors (conservative deposition)
    DynamicList<label> near;
    DynamicList<scalar> weight;
    shapeCells_.clear();
    shapeWeights_.clear();
    shapeStart_.setSize(x.size() + 1);
    shapeStart_[0] = 0;
    shapeSum_.setSize(nReal);
    shapeSum_ = 0;
    forAll(x, i)
    {
        if (magSqr(localBb_.nearest(x[i]) - x[i]) < sqr(R))
        {
            shapeAt(x[i], near, weight);
            shapeCells_.append(near);
            shapeWeights_.append(weight);
            shapeSum_[origin[i]] += sum(weight);
        }
        shapeStart_[i + 1] = shapeCells_.size();
    }
    // Each charge's owner sums the shares of every processor, then tells
    // the processors that hold it in their halo
    halo_->sumToOwners(shapeSum_);
    halo_->updateHalo(shapeSum_);

    forAll(shapeSum_, i)
    {
        if (!(shapeSum_[i] > 0))
        {
            FatalIOErrorInFunction(coeffs_)
                << "No cell centre lies within radius " << R << " m of the "
                << "charge at " << x[i] << ": entry radius in "
                << coeffs_.name().c_str() << " must exceed the cell size "
                << "(a few cell sizes for accuracy)" << exit(FatalIOError);
        }
    }
}


void Foam::meshPoisson::composeSourceMaps(const label nReal)
{
    // Copies and images come after the source they were made from
    sourceT_.setSize(nReal + srcOf_.size());
    sourceSign_.setSize(sourceT_.size());
    for (label i = 0; i < nReal; ++i)
    {
        sourceT_[i] = tensor::I;
        sourceSign_[i] = 1;
    }
    forAll(srcOf_, j)
    {
        const label s = srcOf_[j];
        sourceT_[nReal + j] = srcT_[j] & sourceT_[s];
        sourceSign_[nReal + j] = srcSign_[j]*sourceSign_[s];
    }
}


void Foam::meshPoisson::depositShaped
(
    const UList<scalar>& q,
    const labelUList& origin
)
{
    const scalarField& V = mesh_.V().field();
    scalarField& rho = rhoQ_.primitiveFieldRef();
    rho = 0;
    forAll(q, i)
    {
        const scalar qw = q[i]/shapeSum_[origin[i]];
        for (label k = shapeStart_[i]; k < shapeStart_[i + 1]; ++k)
        {
            const label celli = shapeCells_[k];
            rho[celli] += qw*shapeWeights_[k]/V[celli];
        }
    }
}


void Foam::meshPoisson::averageOverShapes
(
    const labelUList& origin,
    const label nReal
)
{
    // The deposition's weights again; a copy's or image's cells hold the
    // part of the shape that lies beyond a cyclic patch or a wall, where
    // the field is the mapped one, sign T^T E (see Description)
    const vectorField& E = E_.primitiveField();
    shapeField_.setSize(nReal);
    shapeField_ = Zero;
    for (label i = 0; i < shapeStart_.size() - 1; ++i)
    {
        if (shapeStart_[i + 1] == shapeStart_[i])
        {
            continue;
        }
        vector sum(Zero);
        for (label k = shapeStart_[i]; k < shapeStart_[i + 1]; ++k)
        {
            sum += shapeWeights_[k]*E[shapeCells_[k]];
        }
        shapeField_[origin[i]] +=
            i < nReal ? sum : sourceSign_[i]*(sourceT_[i].T() & sum);
    }
    removeSelfFields(origin, nReal);
    // The owners' sums (the halo entries are not used)
    halo_->sumToOwners(shapeField_);
    shapeField_ /= shapeSum_;
}


void Foam::meshPoisson::unfoldedCellsNear
(
    const point& y,
    const scalar r,
    const UList<vector>& translations,
    DynamicList<label>& cells,
    DynamicList<vector>& shifts
) const
{
    DynamicList<scalar> dist;
    cellsNear(y, r, cells, dist);
    shifts.setSize(cells.size());
    shifts = Zero;
    if (translations.empty())
    {
        return;
    }
    // A cell within reach twice (a period shorter than the patch's
    // diameter) is taken once, where it is nearest to y (the cyclic
    // faces between its two sides then hold fixed values)
    Map<label> at(2*cells.size());
    forAll(cells, j)
    {
        at.insert(cells[j], j);
    }
    DynamicList<scalar> moreDist;
    DynamicList<label> more;
    for (const vector& t : translations)
    {
        if (magSqr(localBb_.nearest(y + t) - y - t) < sqr(r))
        {
            cellsNear(y + t, r, more, moreDist);
            forAll(more, k)
            {
                const auto iter = at.cfind(more[k]);
                if (!iter.found())
                {
                    at.insert(more[k], cells.size());
                    cells.append(more[k]);
                    shifts.append(-t);
                    dist.append(moreDist[k]);
                }
                else if (moreDist[k] < dist[*iter])
                {
                    shifts[*iter] = -t;
                    dist[*iter] = moreDist[k];
                }
            }
        }
    }
}


void Foam::meshPoisson::shapeWithCopies
(
    const point& y,
    const UList<vector>& translations,
    DynamicList<label>& cells,
    DynamicList<scalar>& w
) const
{
    shapeAt(y, cells, w);
    DynamicList<label> more;
    DynamicList<scalar> moreW;
    for (const vector& t : translations)
    {
        if (magSqr(localBb_.nearest(y + t) - y - t) < sqr(radius_))
        {
            shapeAt(y + t, more, moreW);
            cells.append(more);
            w.append(moreW);
        }
    }
}


void Foam::meshPoisson::nearestWallPlane
(
    const point& y,
    const scalar r,
    point& p,
    vector& n,
    scalar& sign
) const
{
    // The wall face nearest to y within r: the wall's tangent plane at
    // the foot of y (as addWallImages) and its image sign
    scalar best = sqr(r);
    label nearest = -1;
    forAll(wallC_, f)
    {
        const scalar d2 = magSqr(wallC_[f] - y);
        if (d2 < best)
        {
            best = d2;
            nearest = f;
        }
    }
    if (nearest < 0)
    {
        return;
    }
    sign = wallSign_[nearest];
    wallTangentPlane(nearest, y, p, n);
}


bool Foam::meshPoisson::clearOfProcessors(const point& y) const
{
    // The shape at y reaches no processor patch (faces within R: the
    // neighbour holds part of it); faces within R belong to cells within
    // 2R, the radius being larger than a cell
    DynamicList<label> cells;
    DynamicList<scalar> dist;
    cellsNear(y, 2*radius_, cells, dist);
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const pointField& pts = mesh_.points();
    for (const label celli : cells)
    {
        for (const label f : mesh_.cells()[celli])
        {
            if
            (
                mesh_.isInternalFace(f)
             || !isA<processorPolyPatch>(pbm[pbm.whichPatch(f)])
            )
            {
                continue;
            }
            const point& Cf = mesh_.faceCentres()[f];
            const vector n(normalised(mesh_.faceAreas()[f]));
            const scalar d = (Cf - y) & n;
            if (d >= radius_)
            {
                continue;
            }
            scalar rf = 0;
            for (const label pointi : mesh_.faces()[f])
            {
                rf = max(rf, mag(pts[pointi] - Cf));
            }
            if (mag(y + d*n - Cf) <= 1.001*rf)
            {
                return false;
            }
        }
    }
    return true;
}


void Foam::meshPoisson::shapeWeightsHere
(
    const labelUList& origin,
    const label nReal,
    scalarField& wLocal,
    scalarField& wImaged
) const
{
    // Per charge: the weight of its shape on this processor, its cyclic
    // copies' included (a translation, T = I and sign 1), and that of its
    // wall images
    wLocal.setSize(nReal);
    wLocal = 0;
    wImaged.setSize(nReal);
    wImaged = 0;
    for (label i = 0; i < shapeStart_.size() - 1; ++i)
    {
        scalar w = 0;
        for (label k = shapeStart_[i]; k < shapeStart_[i + 1]; ++k)
        {
            w += shapeWeights_[k];
        }
        if (i < nReal || (sourceT_[i] == tensor::I && sourceSign_[i] == 1))
        {
            wLocal[origin[i]] += w;
        }
        else
        {
            wImaged[origin[i]] += w;
        }
    }
}


void Foam::meshPoisson::removeSelfFields
(
    const labelUList& origin,
    const label nReal
)
{
    if (!selfField_.valid())
    {
        return;
    }
    const List<vector> translations(periodicTranslations());
    const unfoldedNeighbourhood neighbourhood{*this, translations};
    const shapeAndCopies shape{*this, translations};
    const wallPlaneNear wallPlane{*this};
    const shapeClear clear{*this};
    pointSelfField_.setSize(nReal);
    pointSelfField_ = Zero;
    scalarField wLocal, wImaged;
    shapeWeightsHere(origin, nReal, wLocal, wImaged);
    // In parallel a shape split between processors is solved by its owner
    // on the patch gathered from every processor, unless imaged on any
    // (meshUniform_ is the same on every processor, true in serial)
    const bool gatherPatches = !meshUniform_;
    // Each charge's sources (itself, its copies and its images), made
    // when a shape cut by a wall first needs them
    labelListList sourcesOf;
    DynamicList<label> split;
    DynamicList<scalar> splitVref;
    scalarField imaged;
    if (gatherPatches)
    {
        imaged = wImaged;
        halo_->sumToOwners(imaged);
    }
    const scalarField& V = mesh_.V().field();
    for (label i = 0; i < nReal; ++i)
    {
        // The whole shape on this processor, no wall image deposited
        // (else left as it is: a shape cut by a wall, or split between
        // processors and owned elsewhere); its cell: the one of its own
        // (not a copy's) with the largest weight
        const bool splitHere =
            wLocal[i] + wImaged[i] < (1 - 1e-12)*shapeSum_[i];
        if (wImaged[i] > 0 && !splitHere)
        {
            if (sourcesOf.empty())
            {
                sourcesOf = invertOneToMany(nReal, origin);
            }
            removeImagedSelfField(i, sourcesOf[i], neighbourhood);
            continue;
        }
        if (wImaged[i] > 0 || splitHere)
        {
            if
            (
                splitHere && gatherPatches
             && i < halo_->nLocal() && !(imaged[i] > 0)
             && shapeStart_[i + 1] > shapeStart_[i]
            )
            {
                split.append(i);
                splitVref.append(V[shapeCells_[shapeStart_[i]]]);
            }
            continue;
        }
        const label celli = shapeCell(i);
        if (celli < 0)
        {
            continue;
        }
        const scalar qw = qs_[i]*wLocal[i];
        vector s(Zero);
        bool atCharge =
            selfFieldSampling_ == selfFieldSamplingType::charges;
        if (!atCharge)
        {
            const bool automatic =
                selfFieldSampling_ == selfFieldSamplingType::automatic;
            scalar scale = 0;
            s = selfField_->field
            (
                xs_[i], celli, neighbourhood, shape, wallPlane, clear,
                automatic ? &scale : nullptr
            );
            // auto decides on the scale of the points' interpolation error
            // (cached: each point is solved once): shapeField_[i]/
            // shapeSum_[i] is the mesh field at the charge (the whole
            // shape is here), its self field included
            const vector self(qw*s/shapeSum_[i]);
            atCharge =
                automatic
             && mag(qw)*scale/shapeSum_[i]
              > selfFieldAtChargeRatio*mag(shapeField_[i]/shapeSum_[i] - self);
        }
        if (atCharge && gatherPatches && patchCrossesProcessors(xs_[i]))
        {
            // Its patch reaches another processor's cells: solved on the
            // patch gathered from them (at the points it is cut there)
            split.append(i);
            splitVref.append(V[celli]);
            continue;
        }
        if (atCharge)
        {
            s = selfField_->fieldAtCharge
            (
                xs_[i], celli, neighbourhood, shape, wallPlane, clear
            );
        }
        else if (selfFieldSampling_ == selfFieldSamplingType::automatic)
        {
            pointSelfField_[i] = s;
        }
        shapeField_[i] -= qw*s;
    }
    if (gatherPatches)
    {
        removeSplitSelfFields(split, splitVref, neighbourhood, shape, wallPlane);
    }
}


template<class Neighbourhood>
void Foam::meshPoisson::removeImagedSelfField
(
    const label i,
    const labelUList& sources,
    const Neighbourhood& neighbourhood
)
{
    // Solved at the charge (its images move with it: no points' cache),
    // unless the self fields are only sampled at the points
    if (selfFieldSampling_ == selfFieldSamplingType::points)
    {
        return;
    }
    const label celli = shapeCell(i);
    if (celli < 0 || selfField_->uniformAt(celli, neighbourhood))
    {
        return;
    }
    const label nReal = shapeSum_.size();
    shapeSelfField::localProblem lp;
    DynamicList<point> x(1, xs_[i]);
    DynamicList<scalar> q(1, scalar(1));
    DynamicList<tensor> T(1, tensor::I);
    DynamicList<label> rows;
    DynamicList<scalar> w;
    DynamicList<label> src;
    const pairwiseCoulomb coulomb(epsilonR_);
    for (const label k : sources)
    {
        if (k >= nReal)
        {
            if (sourceSign_[k] == 1 && sourceT_[k] == tensor::I)
            {
                // A cyclic copy: its cells lie across the cyclic patch
                return;
            }
            // The images' force on the whole shape (H&E Eq. 8-73)
            lp.exact +=
                sourceSign_[k]
               *s2Shape::pairField(coulomb.k(), radius_, xs_[i] - xs_[k]);
            x.append(xs_[k]);
            q.append(sourceSign_[k]);
            T.append(sourceT_[k]);
        }
        for (label j = shapeStart_[k]; j < shapeStart_[k + 1]; ++j)
        {
            rows.append(shapeCells_[j]);
            w.append(shapeWeights_[j]);
            src.append(x.size() - 1);
        }
    }
    lp.x.transfer(x);
    lp.q.transfer(q);
    lp.T.transfer(T);
    lp.rows.transfer(rows);
    lp.w.transfer(w);
    lp.src.transfer(src);
    shapeField_[i] -=
        qs_[i]*sum(lp.w)
       *selfField_->imagedFieldAtCharge(xs_[i], neighbourhood, lp);
}


Foam::label Foam::meshPoisson::shapeCell(const label i) const
{
    label celli = -1;
    scalar wMax = 0;
    for (label k = shapeStart_[i]; k < shapeStart_[i + 1]; ++k)
    {
        if (shapeWeights_[k] > wMax)
        {
            wMax = shapeWeights_[k];
            celli = shapeCells_[k];
        }
    }
    return celli;
}


bool Foam::meshPoisson::patchCrossesProcessors(const point& x) const
{
    const scalar reach = selfField_->patchRadius();
    const List<boundBox>& boxes = processorHalo::processorBoxes(mesh_);
    forAll(boxes, proci)
    {
        if (proci != Pstream::myProcNo() && boxes[proci].overlaps(x, sqr(reach)))
        {
            return true;
        }
    }
    return false;
}


template<class Neighbourhood, class Shape>
Foam::List<Foam::DynamicList<Foam::shapeSelfField::patchPart>>
Foam::meshPoisson::gatherPatchParts
(
    const UList<point>& x,
    const UList<scalar>& Vref,
    const UList<List<point>>& xSources,
    const Neighbourhood& neighbourhood,
    const Shape& shape
) const
{
    // Requests to every processor whose mesh is within the patch radius
    const scalar reach = selfField_->patchRadius();
    const List<boundBox>& boxes = processorHalo::processorBoxes(mesh_);
    const label nProcs = Pstream::nProcs();
    List<DynamicList<label>> reqId(nProcs);
    List<DynamicList<point>> reqX(nProcs);
    List<DynamicList<scalar>> reqV(nProcs);
    List<DynamicList<List<point>>> reqSources(nProcs);
    forAll(x, r)
    {
        for (label proci = 0; proci < nProcs; ++proci)
        {
            if (boxes[proci].overlaps(x[r], sqr(reach)))
            {
                reqId[proci].append(r);
                reqX[proci].append(x[r]);
                reqV[proci].append(Vref[r]);
                reqSources[proci].append(xSources[r]);
            }
        }
    }
    PstreamBuffers requests(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (reqId[proci].size())
        {
            UOPstream os(proci, requests);
            os << reqId[proci] << reqX[proci] << reqV[proci]
               << reqSources[proci];
        }
    }
    labelList requestSizes;
    requests.finishedSends(requestSizes);

    // Each processor's part of each patch asked for
    PstreamBuffers answers(Pstream::commsTypes::nonBlocking);
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (!requestSizes[proci])
        {
            continue;
        }
        UIPstream is(proci, requests);
        const labelList ids(is);
        const pointField xr(is);
        const scalarField Vr(is);
        const List<List<point>> sources(is);
        List<shapeSelfField::patchPart> parts(ids.size());
        forAll(ids, j)
        {
            DynamicList<label> cells, shapeCells;
            DynamicList<vector> shifts;
            DynamicList<scalar> w;
            neighbourhood(xr[j], reach, cells, shifts);
            shape(xr[j], shapeCells, w);
            parts[j] = selfField_->part
            (
                cells, shifts, shapeCells, w, xr[j], reach, Vr[j],
                cellGid_, neighbourGid_
            );
            parts[j].sourceCells.setSize(sources[j].size());
            parts[j].sourceWeights.setSize(sources[j].size());
            forAll(sources[j], s)
            {
                shape(sources[j][s], shapeCells, w);
                parts[j].sourceCells[s] =
                    UIndirectList<label>(cellGid_, shapeCells)();
                parts[j].sourceWeights[s] = w;
            }
        }
        UOPstream os(proci, answers);
        os << ids;
        for (const shapeSelfField::patchPart& p : parts)
        {
            os << p;
        }
    }
    labelList answerSizes;
    answers.finishedSends(answerSizes);

    List<DynamicList<shapeSelfField::patchPart>> partsOf(x.size());
    for (label proci = 0; proci < nProcs; ++proci)
    {
        if (!answerSizes[proci])
        {
            continue;
        }
        UIPstream is(proci, answers);
        const labelList ids(is);
        for (const label r : ids)
        {
            shapeSelfField::patchPart p;
            is >> p;
            partsOf[r].append(p);
        }
    }
    return partsOf;
}


template<class Neighbourhood, class Shape, class WallPlane>
void Foam::meshPoisson::removeSplitSelfFields
(
    const labelUList& split,
    const UList<scalar>& Vref,
    const Neighbourhood& neighbourhood,
    const Shape& shape,
    const WallPlane& wallPlane
)
{
    const scalar reach = selfField_->patchRadius();
    const List<DynamicList<shapeSelfField::patchPart>> partsOf
    (
        gatherPatchParts
        (
            pointField(xs_, split), Vref,
            List<List<point>>(split.size()), neighbourhood, shape
        )
    );
    // The owners solve
    forAll(split, r)
    {
        const label i = split[r];
        point wallPoint(Zero);
        vector wallNormal(Zero);
        scalar imageSign = 0;
        wallPlane(xs_[i], reach, wallPoint, wallNormal, imageSign);
        const vector s
        (
            selfField_->solveParts
            (
                partsOf[r], xs_[i], wallPoint, wallNormal, imageSign
            )
        );
        shapeField_[i] -= qs_[i]*shapeSum_[i]*s;
    }
}


void Foam::meshPoisson::checkCoeffs() const
{
    if (correction_ == correctionType::shaped && coeffs_.found("interpolation"))
    {
        FatalIOErrorInFunction(coeffs_)
            << "Entry interpolation in " << coeffs_.name().c_str()
            << " applies to correction cellCentroid only: the shaped"
            << " correction averages the mesh field over each charge's own"
            << " shape with its deposition weights (momentum conserving);"
            << " remove the entry" << exit(FatalIOError);
    }
    const fvSolution& fvSol = mesh_;
    if (!fvSol.subDict("solvers").found(Phi_.name()))
    {
        FatalIOErrorInFunction(fvSol)
            << "system/fvSolution has no solver entry for " << Phi_.name()
            << " (the electric potential of the mesh far field), e.g."
            << nl << "    Phi { solver PCG; preconditioner DIC; "
            << "tolerance 1e-10; relTol 0; }" << exit(FatalIOError);
    }
}


void Foam::meshPoisson::printSetup() const
{
    Info<< "    Mesh far field: div(eps grad Phi) = -rho_q, epsilonR = "
        << epsilonR_ << ", correction " << correctionTypeNames[correction_]
        << (correction_ == correctionType::shaped ? " (S2 radius " : " (rCut ")
        << radius_ << " m";
    if (correction_ == correctionType::shaped)
    {
        Info<< ", images in " << nWallFaces_ << " wall faces";
        if (selfFieldRadius_ > 0)
        {
            Info<< ", self field removed at the "
                << selfFieldSamplingTypeNames[selfFieldSampling_]
                << " (patch radius " << selfFieldPatchRadius() << " m)";
        }
        if (lattice_.valid())
        {
            Info<< ", lattice correction (cubic cells of " << latticeH_
                << " m) of charges with at most " << latticeMaxSources_
                << " sources within 2R";
        }
    }
    Info<< "), "
        << (
               correction_ == correctionType::shaped
             ? word("field averaged over the shapes")
             : "interpolation " + interpolationScheme_
           )
        << ", solved every " << solveInterval_ << " evaluation(s)"
        << ", " << nNonOrthCorr_ << " non-orthogonal corrector(s) (largest"
        << " non-orthogonality " << radToDeg(maxNonOrthogonality_)
        << " deg)";
    if (periodicShifts_.size())
    {
        Info<< ", periodic translations " << periodicShifts_;
    }
    if (Phi_.needReference())
    {
        Info<< ", neutralising background (no fixed potential)";
    }
    Info<< endl;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::meshPoisson::meshPoisson(const fvMesh& mesh, const dictionary& coeffs)
:
    mesh_(mesh),
    coeffs_(coeffs),
    epsilonR_
    (
        getPositiveOrDefault
        (
            coeffs, "epsilonR", 1, std::numeric_limits<scalar>::max(), "",
            " (relative permittivity of the medium)"
        )
    ),
    correction_
    (
        correctionTypeNames.lookupOrDefault
        (
            "correction",
            coeffs,
            correctionType::shaped
        )
    ),
    radius_(readRadius()),
    interpolationScheme_
    (
        coeffs.lookupOrDefault<word>("interpolation", "cell")
    ),
    solveInterval_
    (
        getCheckedOrDefault<label>
        (
            coeffs, "solveInterval", 1,
            [](const label n) { return n >= 1; },
            ": it must be >= 1 (solve the potential every n-th force"
            " evaluation)"
        )
    ),
    maxNonOrthogonality_(maxNonOrthogonality()),
    nNonOrthCorr_(readNonOrthCorrectors()),
    nonOrthTolerance_(readNonOrthTolerance()),
    selfFieldRadius_(readSelfFieldRadius()),
    selfFieldSampling_(readSelfFieldSampling()),
    latticeMaxSources_
    (
        getCheckedOrDefault<label>
        (
            coeffs, "latticeCorrectionSources", 8,
            [](const label n) { return n >= 0; },
            ": it must be >= 0 (the most sources within 2 radii of a charge"
            " for which the pair correction, lattice or patch, is made;"
            " 0: none)"
        )
    ),
    patchPairMaxCharges_
    (
        getCheckedOrDefault<label>
        (
            coeffs, "patchPairCorrectionCharges", 16,
            [](const label n) { return n >= 0; },
            ": it must be >= 0 (the most charges that get the patch pair"
            " correction, one patch solve each; 0: none)"
        )
    ),
    gradient_
    (
        mesh,
        readChoice
        (
            coeffs, "gradient", potentialGradient::schemeTypeNames,
            potentialGradient::schemeType::leastSquares
        )
    ),
    latticeH_(0),
    latticeOrigin_(Zero),
    nEvaluations_(0),
    solved_(false),
    periodicShifts_(),
    Phi_
    (
        IOobject
        (
            "Phi",
            mesh.time().timeName(),
            mesh,
            IOobject::READ_IF_PRESENT,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimPotential, Zero),
        defaultPhiTypes(mesh)
    ),
    rhoQ_
    (
        IOobject
        (
            "rhoQ",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        mesh,
        dimensionedScalar(dimChargeDensity, Zero)
    ),
    E_
    (
        IOobject
        (
            "E",
            mesh.time().timeName(),
            mesh,
            IOobject::NO_READ,
            IOobject::AUTO_WRITE
        ),
        -gradient_.grad(Phi_)
    ),
    shapeFresh_(false),
    farValid_(false),
    wallRMax_(0),
    nWallFaces_(0),
    nRealSources_(-1),
    binOrigin_(Zero),
    binSize_(1),
    nBins_(1, 1, 1)
{
    checkCoeffs();

    meshUniform_ = true;
    findPeriodicShifts();
    binCells();
    localBb_ = boundBox(mesh.points(), false);
    localBb_.inflate(1e-6);

    if (correction_ == correctionType::shaped)
    {
        setUpLattice();
        collectWallFaces();
    }

    printSetup();
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

void Foam::meshPoisson::resetPotential()
{
    // The boundary conditions (electrodes) stay
    Phi_.primitiveFieldRef() = Zero;
    Phi_.correctBoundaryConditions();
}


void Foam::meshPoisson::solve()
{
    // Permittivity [F/m = A^2 s^4 kg^-1 m^-3]
    const dimensionedScalar eps
    (
        "eps",
        dimensionSet(-1, -3, 4, 0, 0, 2, 0),
        pairwiseCoulomb::vacuumPermittivity*epsilonR_
    );

    volScalarField rho(rhoQ_);
    if (Phi_.needReference())
    {
        // Neutralising background: the potential of a periodic or
        // insulated box exists only for zero net charge
        rho -=
            fvc::domainIntegrate(rho)
           /dimensionedScalar("V", dimVolume, gSum(mesh_.V()));
    }

    if
    (
        correction_ == correctionType::shaped
     && selfFieldRadius_ > 0
     && !selfField_.valid()
    )
    {
        fvScalarMatrix L(gradient_.laplacian(eps, Phi_));
        placeOnWallSurface(L);
        selfField_.reset
        (
            new shapeSelfField
            (
                mesh_,
                gradient_,
                epsilonR_,
                L.upper(),
                L.internalCoeffs(),
                radius_,
                selfFieldPatchRadius(),
                nNonOrthCorr_,
                nonOrthTolerance_,
                wallCoeffScale_
            )
        );
        if (Pstream::parRun())
        {
            cellGid_ =
                identity
                (
                    mesh_.nCells(), globalIndex(mesh_.nCells()).localStart()
                );
            syncTools::swapBoundaryCellList(mesh_, cellGid_, neighbourGid_);
            // Uniform on every processor, with one cell volume
            const scalarField& V = mesh_.V().field();
            meshUniform_ =
                returnReduce(selfField_->uniform(), andOp<bool>())
             && gMax(V) - gMin(V) <= 1e-6*gMin(V);
        }
    }

    // The non-orthogonal correction is explicit (from the Phi of the last
    // solve): re-solve with it updated
    for (label corr = 0; corr <= nNonOrthCorr_; ++corr)
    {
        fvScalarMatrix PhiEqn
        (
            gradient_.laplacian(eps, Phi_) + rho
        );
        placeOnWallSurface(PhiEqn);
        // Only used when no patch fixes the potential
        PhiEqn.setReference(Pstream::master() ? 0 : -1, 0);
        const scalar residual = PhiEqn.solve().initialResidual();
        if (residual < nonOrthTolerance_)
        {
            // The correction no longer changes the potential
            break;
        }
    }

    E_ = -gradient_.grad(Phi_);
    if (correction_ == correctionType::cellCentroid)
    {
        EInterp_ = interpolation<vector>::New(interpolationScheme_, E_);
    }
    solved_ = true;
}


void Foam::meshPoisson::addTransform
(
    const label src,
    const tensor& T,
    const vector& b,
    const scalar sign
)
{
    srcOf_.append(src);
    srcT_.append(T);
    srcB_.append(b);
    srcSign_.append(sign);
}


bool Foam::meshPoisson::reapplyTransforms
(
    const UList<point>& x,
    const UList<scalar>& q
)
{
    if (x.size() != nRealSources_ || !solved_)
    {
        return false;
    }
    const label nReal = x.size();
    xs_.setSize(nReal + srcOf_.size());
    qs_.setSize(xs_.size());
    SubList<point>(xs_, nReal) = x;
    SubList<scalar>(qs_, nReal) = q;
    forAll(srcOf_, j)
    {
        const label s = srcOf_[j];
        const label i = nReal + j;
        xs_[i] = (srcT_[j] & xs_[s]) + srcB_[j];
        qs_[i] = srcSign_[j]*qs_[s];
        // An image lies within 4 sqrt(3) R of its charge (up to three
        // reflections in walls within 2 R; a charge that left and a new
        // one in its slot would not): else search again
        if
        (
            srcT_[j] != tensor::I
         && magSqr(xs_[i] - xs_[s]) > 48*sqr(radius_)
        )
        {
            return false;
        }
    }
    return true;
}


Foam::scalar Foam::meshPoisson::haloRange() const
{
    // shaped: periodic copies are made within 2.5 R of the box, wall
    // images of the charges within 4 R (addWallImages), the correction
    // reaches 2 R; cellCentroid: copies within 1.5 R, correction R
    return (correction_ == correctionType::shaped ? 4 : 1.5)*radius_;
}


Foam::scalar Foam::meshPoisson::latticeSpacing() const
{
    const scalarField& V = mesh_.V().field();
    const scalar h =
        Foam::cbrt(returnReduce(V.size() ? V[0] : 0, maxOp<scalar>()));
    bool cubic = h > 0;
    const scalar tol = 1e-6*h;
    for (const scalar v : V)
    {
        cubic = cubic && mag(v - pow3(h)) <= 3*tol*sqr(h);
    }
    const vectorField& C = mesh_.C().primitiveField();
    const vectorField& Sf = mesh_.Sf().primitiveField();
    const scalarField& magSf = mesh_.magSf().primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    forAll(nei, f)
    {
        cubic =
            cubic
         && mag(magSf[f] - sqr(h)) <= 2*tol*h
         && mag(C[nei[f]] - C[own[f]] - (h/magSf[f])*Sf[f]) <= tol;
    }
    for (const fvPatch& p : mesh_.boundary())
    {
        if (isA<emptyPolyPatch>(p.patch()))
        {
            cubic = false;
            continue;
        }
        // Coupled patches: the neighbouring cell's centre, h away;
        // others: the face centre, h/2 away
        const scalar d = p.coupled() ? h : h/2;
        const vectorField delta(p.delta());
        const vectorField n(p.nf());
        forAll(p, i)
        {
            cubic =
                cubic
             && mag(p.magSf()[i] - sqr(h)) <= 2*tol*h
             && mag(delta[i] - d*n[i]) <= tol;
        }
    }
    // The boundary's faces on at most six planes (a box or a duct): the
    // images of a plane are the lattice's, but a stepped wall (a
    // castellated snappyHexMesh) is not its images' planes
    facePlanes planes(1e-6, tol);
    for (const fvPatch& p : mesh_.boundary())
    {
        if (p.coupled() || !cubic)
        {
            continue;
        }
        const vectorField n(p.nf());
        forAll(p, i)
        {
            planes.insert(n[i], p.Cf()[i]);
            cubic = cubic && planes.size() <= 6;
        }
    }
    if (!returnReduce(cubic, andOp<bool>()))
    {
        return 0;
    }
    planes.mergeProcessors();
    return planes.size() <= 6 ? h : 0;
}


void Foam::meshPoisson::setUpLattice()
{
    // Only where it is exact (the mesh is the lattice; a planar wall on
    // the cells' faces images the lattice onto itself) and the shape at
    // most 4 cells (its cost per pair grows as (R/h)^6; at 4 cells the
    // lattice's own error is within a few %)
    if (latticeMaxSources_ == 0)
    {
        return;
    }
    const scalar h = latticeSpacing();
    if (!(h > 0) || radius_ > 4*h*(1 + 1e-9))
    {
        return;
    }
    latticeH_ = h;
    latticeOrigin_ = gMin(mesh_.points());
    // Offsets between the cells of two shapes (within R of their centres)
    // whose centres lie within 4R
    lattice_.reset
    (
        new latticeGreensFunction
        (
            label(std::ceil((latticeImageReach() + 2*radius_)/h)) + 2
        )
    );
}


Foam::scalar Foam::meshPoisson::latticeImageReach() const
{
    // The lattice's error of a pair falls as (h/r)^2: about 1 % of the
    // pair's field at 16 cells (latticePairError.py)
    return max(4*radius_, 16*latticeH_);
}


void Foam::meshPoisson::latticeSources
(
    const labelUList& targets,
    const UList<point>& xTargets,
    DynamicList<label>& target,
    DynamicList<point>& xSource,
    DynamicList<scalar>& qSource
) const
{
    const scalar R = radius_;
    // Each target's sources: the instances of the charges (themselves and
    // their cyclic translations) within 4R and their images within reach,
    // the target's own images. Made here from the charges, not taken from
    // the deposited copies and images (those reach less far, and differ
    // between serial and parallel runs); an instance's images are its
    // charge's, translated
    const label nReal = nRealSources_;
    List<vector> shifts(1, Zero);
    shifts.append(periodicTranslations());
    pointField xInst(nReal*shifts.size());
    forAll(shifts, k)
    {
        for (label i = 0; i < nReal; ++i)
        {
            xInst[k*nReal + i] = xs_[i] + shifts[k];
        }
    }
    DynamicList<labelPair> charges;
    forAll(targets, t)
    {
        charges.append(labelPair(t, targets[t]));
    }
    forPairsWithinCutoff
    (
        xTargets, xInst, 4*R, -1,
        [&](const label t, const label s, const vector&, const scalar r2)
        {
            if (s != targets[t] && r2 > 0)
            {
                charges.append(labelPair(t, s));
            }
        }
    );
    // The images of the charges involved, at their own positions
    labelList slot(nReal, -1);
    DynamicList<point> xImaged;
    for (const labelPair& c : charges)
    {
        const label i = c.second() % nReal;
        if (slot[i] < 0)
        {
            slot[i] = xImaged.size();
            xImaged.append(xs_[i]);
        }
    }
    const scalar reach = latticeImageReach();
    DynamicList<label> imageOf;
    DynamicList<point> xImage;
    DynamicList<scalar> signImage;
    forWallImages
    (
        xImaged, 0.5*reach,
        [&](const label j, const tensor& T, const vector& b, const scalar sgn)
        {
            imageOf.append(j);
            xImage.append((T & xImaged[j]) + b);
            signImage.append(sgn);
        }
    );
    // forWallImages visits the points in order
    labelList imageStart(xImaged.size() + 1, 0);
    for (const label j : imageOf)
    {
        ++imageStart[j + 1];
    }
    for (label j = 0; j < xImaged.size(); ++j)
    {
        imageStart[j + 1] += imageStart[j];
    }
    for (const labelPair& c : charges)
    {
        const label t = c.first();
        const label i = c.second() % nReal;
        const vector& shift = shifts[c.second()/nReal];
        if (c.second() != targets[t])
        {
            target.append(t);
            xSource.append(xInst[c.second()]);
            qSource.append(qs_[i]);
        }
        for (label j = imageStart[slot[i]]; j < imageStart[slot[i] + 1]; ++j)
        {
            const point y(xImage[j] + shift);
            if (magSqr(y - xTargets[t]) < sqr(reach))
            {
                target.append(t);
                xSource.append(y);
                qSource.append(signImage[j]*qs_[i]);
            }
        }
    }

}


void Foam::meshPoisson::addLatticeCorrection
(
    const UList<point>& xT,
    const labelUList& nNear
)
{
    // On a uniform mesh the mesh's field of one S2 shape on another is the
    // lattice's (latticeGreensFunction), the walls' response that of the
    // images (a planar wall on the cells' faces maps the lattice onto
    // itself). At 2-3 cells per radius that is off by several % within
    // about 4R and by ~1 % at 16 cells, scattered with the shapes'
    // positions in their cells (the 7-point Laplacian's truncation error;
    // applications/benchmarks/meshFarField/latticePairError.py). Here it is
    // replaced by the exact S2-S2 field (H&E Eq. 8-73) for the charges
    // within 4R (the halo) and their images and the target's own within
    // latticeImageReach, at a cost of (shape cells)^2 per pair: for
    // targets with at most latticeMaxSources_ sources within 2R, where a
    // pair's error is a large part of the field (isolated charges, pairs,
    // charges near walls; in a dense cloud many sources share the field)
    DynamicList<label> targets;
    DynamicList<point> xTargets;
    forAll(xT, t)
    {
        if (nNear[t] <= latticeMaxSources_)
        {
            targets.append(t);
            xTargets.append(xT[t]);
        }
    }
    if (nEvaluations_ == 1)
    {
        Info<< "    Lattice correction: "
            << returnReduce(targets.size(), sumOp<label>()) << " of "
            << returnReduce(xT.size(), sumOp<label>()) << " charges (at most "
            << latticeMaxSources_ << " sources within 2R)" << endl;
    }
    if (targets.empty())
    {
        return;
    }
    const scalar R = radius_;
    DynamicList<label> target;
    DynamicList<point> xSource;
    DynamicList<scalar> qSource;
    latticeSources(targets, xTargets, target, xSource, qSource);

    const scalar h = latticeH_;
    const scalar Rc = R/h;
    const scalar k = pairwiseCoulomb(epsilonR_).k();
    // 1/(eps h^2): the lattice field's unit
    const scalar unit = 4*constant::mathematical::pi*k/sqr(h);
    const auto latticePosition = [&](const point& x)
    {
        return vector((x - latticeOrigin_)/h) - vector::one/2;
    };
    // Each target's shape once (its sources are not consecutive)
    List<DynamicList<labelVector>> cellsT(targets.size());
    List<DynamicList<scalar>> wT(targets.size());
    forAll(targets, t)
    {
        latticeGreensFunction::shape
        (
            latticePosition(xTargets[t]), Rc, cellsT[t], wT[t]
        );
    }
    DynamicList<labelVector> cellsS;
    DynamicList<scalar> wS;
    forAll(target, j)
    {
        const label t = target[j];
        const vector r(xTargets[t] - xSource[j]);
        const scalar r2 = magSqr(r);
        if (r2 == 0)
        {
            continue;
        }
        latticeGreensFunction::shape(latticePosition(xSource[j]), Rc, cellsS, wS);
        const vector exact(s2Shape::pairField(k, R, r));
        farField_[targets[t]] +=
            qSource[j]
           *(exact - unit*lattice_->pairField(cellsT[t], wT[t], cellsS, wS));
    }
}


void Foam::meshPoisson::patchPairTargets
(
    const UList<point>& xT,
    const labelUList& nNear,
    List<DynamicList<label>>& sources,
    DynamicList<label>& targets,
    DynamicList<label>& split
)
{
    const scalar R = radius_;
    const scalar D = selfField_->patchRadius();
    const label nReal = nRealSources_;
    scalarField wLocal, wImaged;
    shapeWeightsHere(origin_, nReal, wLocal, wImaged);
    scalarField imaged(wImaged);
    if (Pstream::parRun())
    {
        halo_->sumToOwners(imaged);
    }
    // A source is a real charge or a cyclic copy (an image's shape is part
    // of its charge's deposit) not imaged here
    const auto sourceOf = [&](const label s)
    {
        const label i =
            s < nReal ? s
          : sourceSign_[s] == 1 && sourceT_[s] == tensor::I ? origin_[s]
          : -1;
        return i >= 0 && wImaged[i] == 0 ? i : -1;
    };
    const scalarField& V = mesh_.V().field();
    sources.setSize(xT.size());
    forPairsWithinCutoff
    (
        xT, xs_, min(4*R, D - R), 0,
        [&](const label t, const label s, const vector&, const scalar r2)
        {
            if (nNear[t] <= latticeMaxSources_ && r2 > 0 && sourceOf(s) >= 0)
            {
                sources[t].append(s);
            }
        }
    );
    const List<vector> translations(periodicTranslations());
    const unfoldedNeighbourhood neighbourhood{*this, translations};
    const shapeClear clear{*this};
    // The targets (here: shape and patch on this processor; split: not)
    // and their sources whose shapes lie within the patch, two of the
    // target's cells inside its edge
    forAll(xT, t)
    {
        const label celli = shapeCell(t);
        if (sources[t].empty() || celli < 0 || imaged[t] > 0)
        {
            continue;
        }
        const scalar h = cbrt(V[celli]);
        if (R > 4*h*(1 + 1e-9) || selfField_->uniformAt(celli, neighbourhood))
        {
            continue;
        }
        const scalar reach = D - R - 2*h;
        DynamicList<label> inReach;
        for (const label s : sources[t])
        {
            if (magSqr(xT[t] - xs_[s]) < sqr(reach))
            {
                inReach.append(s);
            }
        }
        sources[t].transfer(inReach);
        if (sources[t].empty())
        {
            continue;
        }
        const bool here =
            wLocal[t] >= (1 - 1e-12)*shapeSum_[t]
         && clear(xT[t]) && !patchCrossesProcessors(xT[t]);
        if (here)
        {
            targets.append(t);
        }
        else if (Pstream::parRun())
        {
            split.append(t);
        }
    }
}


void Foam::meshPoisson::keepClearOfWalls
(
    const UList<point>& xT,
    DynamicList<label>& targets,
    UList<DynamicList<label>>& sources
) const
{
    label n = 0;
    for (const label t : targets)
    {
        DynamicList<label> clearSources;
        for (const label s : sources[t])
        {
            if (clearOfWalls(xs_[s]))
            {
                clearSources.append(s);
            }
        }
        sources[t].transfer(clearSources);
        if (sources[t].size() && clearOfWalls(xT[t]))
        {
            targets[n++] = t;
        }
    }
    targets.setSize(n);
}


void Foam::meshPoisson::addPatchPairCorrection
(
    const UList<point>& xT,
    const labelUList& nNear
)
{
    // Where the lattice correction does not apply (curved, graded or
    // non-orthogonal meshes) the mesh's pair field of overlapping shapes is
    // off by several % at 2-3 cells per radius as on the lattice (an O-grid
    // pipe, n = 14, R = 2 mean cells: 6 % for a pair 1.6 R apart). Each
    // sparse target's error is found on one patch about it with every
    // source in reach (shapeSelfField::pairErrors): one factorisation per
    // target and evaluation, so for targets with at most
    // latticeMaxSources_ sources within 2R, and radii of at most 4 cells
    // (above, the error is below 1 % and the patches costly), and only
    // while at most patchPairMaxCharges_ targets need it. In parallel a
    // target whose shape or patch reaches another processor is solved on
    // the patch gathered from every processor within reach (as its self
    // field): the same as in serial
    List<DynamicList<label>> sources;
    DynamicList<label> targets, split;
    patchPairTargets(xT, nNear, sources, targets, split);
    // Only for a few charges: each costs a patch factorisation (about 60 ms
    // on the pipe at 2 cells: a cloud of 200 charges in it would take 15x
    // its solve); a larger sparse cloud pays the counts above
    const label nTargets =
        returnReduce(targets.size() + split.size(), sumOp<label>());
    const bool apply = nTargets <= patchPairMaxCharges_;
    if (nEvaluations_ == 1)
    {
        Info<< "    Patch pair correction: " << (apply ? nTargets : 0)
            << " of " << returnReduce(xT.size(), sumOp<label>())
            << " charges (" << nTargets << " with at most "
            << latticeMaxSources_ << " sources within 2R and one in reach;"
            << " applied to at most " << patchPairMaxCharges_ << ")" << endl;
    }
    if (!apply)
    {
        return;
    }
    const List<vector> translations(periodicTranslations());
    const unfoldedNeighbourhood neighbourhood{*this, translations};
    const shapeAndCopies shape{*this, translations};
    const wallPlaneNear wallPlane{*this};
    // Shapes within R of a wall's tangent plane, imaged on some processor,
    // are not the local problems here; tested only now (each test scans
    // the wall faces)
    keepClearOfWalls(xT, targets, sources);
    keepClearOfWalls(xT, split, sources);
    // Under auto a self field from the points (a strong field) is solved at
    // the charge on the same patch, at the cost of one more back
    // substitution (subtractPairErrors)
    for (const label t : targets)
    {
        const List<point> xS(pointField(xs_, sources[t]));
        vector selfAtCharge(Zero);
        subtractPairErrors
        (
            t,
            sources[t],
            selfField_->pairErrors
            (
                xT[t], xS, exactPairFields(xT[t], xS), neighbourhood, shape,
                wallPlane,
                pointSelfField_[t] != vector::zero ? &selfAtCharge : nullptr
            ),
            selfAtCharge
        );
    }
    if (Pstream::parRun())
    {
        addSplitPairCorrections(xT, split, sources);
    }
}


Foam::List<Foam::vector> Foam::meshPoisson::exactPairFields
(
    const point& x,
    const UList<point>& xS
) const
{
    // Per unit source charge (H&E Eq. 8-73)
    const scalar k = pairwiseCoulomb(epsilonR_).k();
    List<vector> exact(xS.size());
    forAll(xS, j)
    {
        exact[j] = s2Shape::pairField(k, radius_, x - xS[j]);
    }
    return exact;
}


void Foam::meshPoisson::subtractPairErrors
(
    const label t,
    const labelUList& sourcesT,
    const UList<vector>& errors,
    const vector& selfAtCharge
)
{
    forAll(errors, j)
    {
        farField_[t] -= qs_[sourcesT[j]]*errors[j];
    }
    // A self field from the points replaced by the one at the charge:
    // between the points it is off by a few % of itself (0.9 % of the
    // field of a pair 1.6 R apart in the pipe at 2 cells, 0.03 % at the
    // charge), and the points' samples near a processor boundary use
    // patches cut there
    if (pointSelfField_[t] != vector::zero)
    {
        farField_[t] += qs_[t]*(pointSelfField_[t] - selfAtCharge);
    }
}


void Foam::meshPoisson::addSplitPairCorrections
(
    const UList<point>& xT,
    const labelUList& split,
    const UList<DynamicList<label>>& sources
)
{
    const scalarField& V = mesh_.V().field();
    const List<vector> translations(periodicTranslations());
    const unfoldedNeighbourhood neighbourhood{*this, translations};
    const shapeAndCopies shape{*this, translations};
    const wallPlaneNear wallPlane{*this};
    scalarField Vref(split.size());
    List<List<point>> xSplit(split.size());
    forAll(split, r)
    {
        Vref[r] = V[shapeCell(split[r])];
        xSplit[r] = pointField(xs_, sources[split[r]]);
    }
    const List<DynamicList<shapeSelfField::patchPart>> partsOf
    (
        gatherPatchParts
        (
            pointField(xT, split), Vref, xSplit, neighbourhood, shape
        )
    );
    forAll(split, r)
    {
        const label t = split[r];
        point wallPoint(Zero);
        vector wallNormal(Zero);
        scalar imageSign = 0;
        wallPlane
        (
            xT[t], selfField_->patchRadius(), wallPoint, wallNormal, imageSign
        );
        vector selfAtCharge(Zero);
        subtractPairErrors
        (
            t,
            sources[t],
            selfField_->solvePairParts
            (
                partsOf[r], xT[t], xSplit[r], exactPairFields(xT[t], xSplit[r]),
                wallPoint, wallNormal, imageSign,
                pointSelfField_[t] != vector::zero ? &selfAtCharge : nullptr
            ),
            selfAtCharge
        );
    }
}


bool Foam::meshPoisson::clearOfWalls(const point& y) const
{
    point p(Zero);
    vector n(Zero);
    scalar sign = 0;
    nearestWallPlane(y, 2*radius_, p, n, sign);
    return sign == 0 || mag((y - p) & n) >= radius_;
}


void Foam::meshPoisson::update
(
    const UList<point>& x,
    const UList<scalar>& q,
    const UList<labelPair>& keys,
    const labelUList& cells
)
{
    const bool solveNow =
        nEvaluations_++ % solveInterval_ == 0 || !solved_;

    // The charges known here: the local ones and the halo
    halo_.reset
    (
        new processorHalo
        (
            processorHalo::processorBoxes(mesh_),
            x,
            haloRange(),
            periodicTranslations()
        )
    );
    const pointField& xK = halo_->points();
    scalarField qK(q);
    halo_->gather(qK);
    List<labelPair> keysK(keys);
    halo_->gather(keysK);
    if (correction_ == correctionType::cellCentroid)
    {
        sourceCellCentres_ = pointField(mesh_.C().primitiveField(), cells);
        halo_->gather(sourceCellCentres_);
    }
    const label nReal = xK.size();
    if (nEvaluations_ == 1 && Pstream::parRun())
    {
        Info<< "    Mesh far field in parallel: of "
            << returnReduce(x.size(), sumOp<label>()) << " charges each"
            << " processor holds its own and at most "
            << returnReduce(nReal - x.size(), maxOp<label>())
            << " of its neighbours' (halo " << haloRange() << " m)" << endl;
    }

    // Sources: the charges, their periodic copies and wall images. Found
    // when solving; in between, the same copies and images of the moved
    // charges (unless the charges changed)
    const bool sourcesFound =
        solveNow || keysK != sourceKeys_ || !reapplyTransforms(xK, qK);
    if (sourcesFound)
    {
        xs_ = xK;
        qs_ = qK;
        sourceKeys_.transfer(keysK);
        srcOf_.clear();
        srcT_.clear();
        srcB_.clear();
        srcSign_.clear();
        addPeriodicCopies
        (
            xs_, qs_, origin_,
            (correction_ == correctionType::shaped ? 2.5 : 1.5)*radius_
        );
        if (correction_ == correctionType::shaped)
        {
            addWallImages(xs_, qs_, origin_);
            composeSourceMaps(nReal);
        }
        nRealSources_ = nReal;
    }

    shapeFresh_ = false;
    if (solveNow)
    {
        if (correction_ == correctionType::shaped)
        {
            shapeWeights(xs_, origin_, nReal);
            depositShaped(qs_, origin_);
        }
        else
        {
            // Each local charge in its cell (Rasera 2022 section 2.3)
            scalarField& rho = rhoQ_.primitiveFieldRef();
            rho = 0;
            const scalarField& V = mesh_.V().field();
            forAll(cells, i)
            {
                rho[cells[i]] += q[i]/V[cells[i]];
            }
        }
        rhoQ_.correctBoundaryConditions();
        solve();
        if (correction_ == correctionType::shaped)
        {
            averageOverShapes(origin_, nReal);
            shapeFresh_ = true;
        }
        farValid_ = false;
    }
    else if (sourcesFound)
    {
        // The charges changed: their far fields afresh (same mesh field)
        farValid_ = false;
    }
}


namespace
{

//- Exact Coulomb minus the S2-S2 pair field of a source of charge q at
//  -r from the target (kq = k q; H&E Eq. 8-73), the shaped correction
inline Foam::vector shapedPairCorrection
(
    const Foam::scalar kq,
    const Foam::scalar R,
    const Foam::vector& r,
    const Foam::scalar r2
)
{
    const Foam::scalar rm = std::sqrt(r2);
    return (kq*Foam::s2Shape::pairDeficit(rm/R)/(r2*rm))*r;
}

} // End anonymous namespace


void Foam::meshPoisson::refreshFarCorrection
(
    const UList<point>& xT,
    const scalar k
)
{
    // The far part: after a solve, or for charges that changed or moved
    // between processors (the shapes' average then at their current
    // positions in the same mesh field)
    bool stale = !farValid_ || farField_.size() != xT.size();
    reduce(stale, orOp<bool>());
    if (!stale)
    {
        return;
    }
    const scalarField& qs = qs_;
    const scalar R = radius_;
    if (!shapeFresh_)
    {
        shapeWeights(xs_, origin_, nRealSources_);
        averageOverShapes(origin_, nRealSources_);
        shapeFresh_ = true;
    }
    farField_ = SubList<vector>(shapeField_, xT.size());
    const bool patchPairs =
        !lattice_.valid() && selfField_.valid()
     && latticeMaxSources_ > 0 && patchPairMaxCharges_ > 0;
    labelList nNear(lattice_.valid() || patchPairs ? xT.size() : 0, 0);

    // The targets are the local charges, the first sources
    forPairsWithinCutoff
    (
        xT, xs_, 2*R, 0,
        [&](const label t, const label s, const vector& r, const scalar r2)
        {
            if (r2 >= R*R)
            {
                farField_[t] += shapedPairCorrection(k*qs[s], R, r, r2);
            }
            if (nNear.size())
            {
                ++nNear[t];
            }
        }
    );
    if (lattice_.valid())
    {
        addLatticeCorrection(xT, nNear);
    }
    else if (patchPairs)
    {
        addPatchPairCorrection(xT, nNear);
    }
    farValid_ = true;
}


void Foam::meshPoisson::addNearField
(
    const UList<point>& xT,
    UList<vector>& E
)
{
    const pointField& xs = xs_;
    const scalarField& qs = qs_;
    const labelList& origin = origin_;
    const label nReal = nRealSources_;
    // The targets are the local charges, the first sources
    const label myStart = 0;

    // Near field: exact Coulomb minus what the mesh carries
    const scalar k = pairwiseCoulomb(epsilonR_).k();
    const auto coincident = [&](const label t)
    {
        FatalErrorInFunction
            << "Two charges at one point " << xT[t] << exit(FatalError);
    };
    if (correction_ == correctionType::shaped)
    {
        refreshFarCorrection(xT, k);

        // The correction within R follows the charges
        const scalar R = radius_;
        forAll(xT, t)
        {
            E[t] += farField_[t];
        }
        forPairsWithinCutoff
        (
            xT, xs, R, myStart,
            [&](const label t, const label s, const vector& r, const scalar r2)
            {
                if (r2 == 0)
                {
                    coincident(t);
                }
                E[t] += shapedPairCorrection(k*qs[s], R, r, r2);
            }
        );
        return;
    }

    // cellCentroid, Rasera Eq. 31: exact minus the centroid-to-centroid
    // field of charges in other cells
    const pointField& cellCentres = sourceCellCentres_;
    pointField cs(cellCentres);
    {
        // Copies share the shift of their charge
        cs.setSize(xs.size());
        for (label i = nReal; i < xs.size(); ++i)
        {
            cs[i] = cellCentres[origin[i]] + (xs[i] - xs[origin[i]]);
        }
    }
    forPairsWithinCutoff
    (
        xT, xs, radius_, myStart,
        [&](const label t, const label s, const vector& r, const scalar r2)
        {
            if (r2 == 0)
            {
                coincident(t);
            }
            E[t] += (k*qs[s]/(r2*std::sqrt(r2)))*r;
            const vector rc(cellCentres[myStart + t] - cs[s]);
            const scalar rc2 = magSqr(rc);
            if (rc2 > 0)
            {
                E[t] -= (k*qs[s]/(rc2*std::sqrt(rc2)))*rc;
            }
        }
    );
}


// ************************************************************************* //
