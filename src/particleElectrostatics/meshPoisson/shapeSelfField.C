/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "shapeSelfField.H"
#include "pairwiseCoulomb.H"
#include "emptyFvPatch.H"
#include "cyclicFvPatch.H"
#include "surfaceFields.H"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/MetisSupport>
#include <Eigen/QR>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::shapeSelfField::shapeSelfField
(
    const fvMesh& mesh,
    const scalar epsilonR,
    const scalarField& upper,
    const FieldField<Field, scalar>& internalCoeffs,
    const scalar shapeRadius,
    const scalar patchRadius,
    const label nNonOrthCorr,
    const scalar tolerance,
    const UList<scalarField>& wallCoeffScale
)
:
    mesh_(mesh),
    eps_(pairwiseCoulomb::vacuumPermittivity*epsilonR),
    k_(pairwiseCoulomb(epsilonR).k()),
    patchRadius_(patchRadius),
    nNonOrthCorr_(nNonOrthCorr),
    tolerance_(tolerance),
    internalCoeff_(upper),
    boundaryCoeff_(mesh.boundary().size()),
    boundaryPoint_(mesh.boundary().size()),
    shapeRadius_(shapeRadius),
    state_(mesh.nCells(), -1),
    pointField_(mesh.nPoints(), Zero),
    pointFound_(mesh.nPoints(), false),
    local_(mesh.nCells(), -1)
{
    // A boundary face as a fixed value: the matrix's own coefficient where
    // the potential has one (fixed value, coupled), else the one a fixed
    // value would have, eps |Sf| with the non-orthogonal delta coefficient
    forAll(mesh.boundary(), patchi)
    {
        const fvPatch& p = mesh.boundary()[patchi];
        scalarField& b = boundaryCoeff_[patchi];
        if (isA<emptyFvPatch>(p))
        {
            b.setSize(p.size(), 0);
            continue;
        }
        // The fixed value's point: the neighbour's centre across a coupled
        // patch, else the face centre
        boundaryPoint_[patchi] = p.Cf();
        if (p.coupled())
        {
            boundaryPoint_[patchi] = p.Cn() + p.delta();
        }
        if (wallCoeffScale.size() && wallCoeffScale[patchi].size())
        {
            // A fixed potential on the wall's surface beyond the face
            // (meshPoisson::placeOnWallSurface): there its coefficient
            // d/(d + s) eps |Sf|/d puts it
            boundaryPoint_[patchi] +=
                p.nf()*(1/wallCoeffScale[patchi] - 1)/p.deltaCoeffs();
        }
        b = -internalCoeffs[patchi];
        const scalarField& magSf = p.magSf();
        const scalarField& dc = mesh.nonOrthDeltaCoeffs().boundaryField()[patchi];
        forAll(b, facei)
        {
            if (!(b[facei] > 0))
            {
                b[facei] = eps_*magSf[facei]*dc[facei];
            }
        }
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::shapeSelfField::circumradius(const label c) const
{
    scalar r = 0;
    for (const label pointi : mesh_.cellPoints()[c])
    {
        r = max(r, mag(mesh_.points()[pointi] - mesh_.C()[c]));
    }
    return r;
}


bool Foam::shapeSelfField::uniformAround
(
    const label c,
    const UList<label>& cells
) const
{
    const scalarField& V = mesh_.V().field();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceVectorField& corr = mesh_.nonOrthCorrectionVectors();
    const label nInternal = mesh_.nInternalFaces();
    const scalar tol = 1e-6;
    for (const label ci : cells)
    {
        if (mag(V[ci] - V[c]) > tol*V[c])
        {
            return false;
        }
        for (const label f : mesh_.cells()[ci])
        {
            if (f >= nInternal)
            {
                // A planar wall of a uniform mesh: faces orthogonal to the
                // line from their cell's centre
                const label patchi = mesh_.boundaryMesh().whichPatch(f);
                const fvPatch& p = mesh_.boundary()[patchi];
                const label facei = f - p.start();
                if (isA<emptyFvPatch>(p))
                {
                    continue;
                }
                const vector d(p.Cf()[facei] - mesh_.C()[ci]);
                const vector n
                (
                    mesh_.Sf().boundaryField()[patchi][facei]
                   /mesh_.magSf().boundaryField()[patchi][facei]
                );
                if (mag(n ^ d) > tol*mag(d))
                {
                    return false;
                }
                continue;
            }
            if (mag(w[f] - 0.5) > tol || mag(corr[f]) > tol)
            {
                return false;
            }
        }
    }
    return true;
}


Foam::scalar Foam::shapeSelfField::tetWeights
(
    const point& x,
    const label c,
    const label facei,
    const label k,
    vector& s
) const
{
    // x = Cc + s1 (Cf - Cc) + s2 (pa - Cc) + s3 (pb - Cc), pa pb the edge
    // from the face's k-th point
    const face& f = mesh_.faces()[facei];
    const point& Cc = mesh_.C()[c];
    const tensor T
    (
        mesh_.faceCentres()[facei] - Cc,
        mesh_.points()[f[k]] - Cc,
        mesh_.points()[f[f.fcIndex(k)]] - Cc
    );
    if (mag(Foam::det(T)) < VSMALL*magSqr(T))
    {
        return -GREAT;
    }
    s = (x - Cc) & Foam::inv(T);
    return min(min(1 - s.x() - s.y() - s.z(), s.x()), min(s.y(), s.z()));
}


Foam::vector Foam::shapeSelfField::interpolate
(
    const point& x,
    const label c
) const
{
    vector valueC(Zero);
    const labelList& cPoints = mesh_.cellPoints()[c];
    for (const label pointi : cPoints)
    {
        valueC += pointField_[pointi];
    }
    valueC /= cPoints.size();

    // In the tetrahedron with the largest smallest barycentric weight
    scalar minWeight = -GREAT;
    vector result(Zero);
    for (const label facei : mesh_.cells()[c])
    {
        const face& f = mesh_.faces()[facei];
        vector valueF(Zero);
        for (const label pointi : f)
        {
            valueF += pointField_[pointi];
        }
        valueF /= f.size();
        forAll(f, k)
        {
            vector s;
            const scalar m = tetWeights(x, c, facei, k, s);
            if (m > minWeight)
            {
                minWeight = m;
                result =
                    (1 - s.x() - s.y() - s.z())*valueC + s.x()*valueF
                  + s.y()*pointField_[f[k]]
                  + s.z()*pointField_[f[f.fcIndex(k)]];
            }
        }
    }
    return result;
}


Foam::label Foam::shapeSelfField::holdingCell
(
    const point& x,
    const label c
) const
{
    const auto minWeight = [&](const label ci)
    {
        scalar best = -GREAT;
        for (const label facei : mesh_.cells()[ci])
        {
            forAll(mesh_.faces()[facei], k)
            {
                vector s;
                best = max(best, tetWeights(x, ci, facei, k, s));
            }
        }
        return best;
    };
    const scalar inside = -1e-9;
    scalar best = minWeight(c);
    if (best >= inside)
    {
        return c;
    }
    label bestCell = c;
    for (const label pointi : mesh_.cellPoints()[c])
    {
        for (const label ci : mesh_.pointCells()[pointi])
        {
            const scalar m = ci == c ? -GREAT : minWeight(ci);
            if (m >= inside)
            {
                return ci;
            }
            if (m > best)
            {
                best = m;
                bestCell = ci;
            }
        }
    }
    return bestCell;
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::List<Foam::vector> Foam::shapeSelfField::solve
(
    const UList<label>& patchCells,
    const UList<vector>& patchShifts,
    const UList<point>& xs,
    const UList<DynamicList<label>>& shapeCells,
    const UList<DynamicList<scalar>>& shapeWeights,
    const point& wallPoint,
    const vector& wallNormal,
    const scalar imageSign
) const
{
    const label n = patchCells.size();
    const scalarField& V = mesh_.V().field();
    const vectorField& C = mesh_.C().primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    const surfaceScalarField& weights = mesh_.weights();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceVectorField& corrVec = mesh_.nonOrthCorrectionVectors();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const scalar k = k_;

    forAll(patchCells, i)
    {
        local_[patchCells[i]] = i;
    }

    // The patch's faces, each once, with the patch-local index of each
    // side (-1: a cell around the patch, holding the exact value at its
    // centre, outAt in the patch's unfolded frame): internal faces and
    // cyclic faces between two patch cells (from the owner patch's side),
    // and boundary faces with a fixed value (at bFaceAt)
    DynamicList<label> faceOwn, faceNei;
    DynamicList<scalar> faceCoeff, faceWeight, faceMagSf;
    DynamicList<vector> faceSf, faceCorr;
    DynamicList<point> faceOutAt;
    DynamicList<label> bFaceRow;
    DynamicList<point> bFaceAt;
    DynamicList<vector> bFaceSf;
    DynamicList<scalar> bFaceCoeff;
    const auto addFace =
        [&]
        (
            const label lo, const label ln, const scalar a, const scalar w,
            const vector& sf, const scalar msf, const vector& corr,
            const point& outAt
        )
    {
        faceOwn.append(lo);
        faceNei.append(ln);
        faceCoeff.append(a);
        faceWeight.append(w);
        faceSf.append(sf);
        faceMagSf.append(msf);
        faceCorr.append(corr);
        faceOutAt.append(outAt);
    };
    forAll(patchCells, i)
    {
        const label c = patchCells[i];
        const vector& shift = patchShifts[i];
        for (const label f : mesh_.cells()[c])
        {
            if (f < nInternal)
            {
                const label lo = local_[own[f]];
                const label ln = local_[nei[f]];
                // Once: from the owner's side, or from a patch neighbour
                // whose owner lies outside
                if ((own[f] == c) || lo < 0)
                {
                    const label o = lo < 0 ? own[f] : nei[f];
                    addFace
                    (
                        lo, ln, internalCoeff_[f], weights[f], Sf[f],
                        magSf[f], corrVec[f], C[o] + shift
                    );
                }
                continue;
            }
            const label patchi = pbm.whichPatch(f);
            const label facei = f - pbm[patchi].start();
            const scalar b = boundaryCoeff_[patchi][facei];
            if (!(b > 0))
            {
                continue;
            }
            // The neighbour's centre across a coupled face (else the face
            // centre), in the patch's unfolded frame
            const point at(boundaryPoint_[patchi][facei] + shift);
            const cyclicFvPatch* cyc =
                isA<cyclicFvPatch>(mesh_.boundary()[patchi]);
            if (cyc)
            {
                // Across a cyclic patch to a patch cell that the unfolded
                // frame puts there: a face between two unknowns
                const label cn = cyc->neighbFvPatch().faceCells()[facei];
                const label ln = local_[cn];
                const scalar delta = mag(at - C[c] - shift);
                if
                (
                    ln >= 0
                 && mag(C[cn] + patchShifts[ln] - at) < 1e-6*delta
                )
                {
                    if (cyc->owner())
                    {
                        addFace
                        (
                            i, ln, b,
                            weights.boundaryField()[patchi][facei],
                            Sf.boundaryField()[patchi][facei],
                            magSf.boundaryField()[patchi][facei],
                            corrVec.boundaryField()[patchi][facei],
                            point::zero
                        );
                    }
                    continue;
                }
            }
            bFaceRow.append(i);
            bFaceAt.append(at);
            bFaceSf.append(Sf.boundaryField()[patchi][facei]);
            bFaceCoeff.append(b);
        }
    }

    // The matrix (negated: symmetric positive definite), factorised once
    // for every shape
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(2*faceOwn.size() + n);
    scalarField diag(n, 0);
    forAll(faceOwn, j)
    {
        const scalar a = faceCoeff[j];
        const label lo = faceOwn[j], ln = faceNei[j];
        if (lo >= 0)
        {
            diag[lo] += a;
        }
        if (ln >= 0)
        {
            diag[ln] += a;
        }
        if (lo >= 0 && ln >= 0)
        {
            triplets.emplace_back(lo, ln, -a);
            triplets.emplace_back(ln, lo, -a);
        }
    }
    forAll(bFaceRow, j)
    {
        diag[bFaceRow[j]] += bFaceCoeff[j];
    }
    forAll(diag, i)
    {
        triplets.emplace_back(i, i, diag[i]);
    }
    Eigen::SparseMatrix<double> M(n, n);
    M.setFromTriplets(triplets.begin(), triplets.end());
    // METIS nested dissection instead of Eigen's default AMD ordering: less
    // fill on these 3-D patches, so the factorisation (most of the self
    // field's cost) runs about 1.5x faster with the same result
    const Eigen::SimplicialLDLT
    <
        Eigen::SparseMatrix<double>,
        Eigen::Lower,
        Eigen::MetisOrdering<int>
    > ldlt(M);

    List<vector> result(xs.size(), Zero);
    scalarField phiOut(faceOwn.size()), phiB(bFaceRow.size());
    vectorField gradOut(faceOwn.size());
    vectorField g(n);
    forAll(xs, s)
    {
        const point& x = xs[s];
        const UList<label>& cells = shapeCells[s];
        const UList<scalar>& w = shapeWeights[s];

        // The exact potential per unit charge (and its gradient) at the
        // cells around the patch and the boundary points: free space, or
        // the charge and its image in the nearest wall's plane
        const point xImage
        (
            x - 2*((x - wallPoint) & wallNormal)*wallNormal
        );
        const auto exact = [&](const point& y, scalar& phiY, vector& gradY)
        {
            const vector r(y - x);
            const scalar mr = mag(r);
            phiY = k/mr;
            gradY = (-k/pow3(mr))*r;
            if (imageSign != 0)
            {
                const vector ri(y - xImage);
                const scalar mri = mag(ri);
                phiY += imageSign*k/mri;
                gradY -= (imageSign*k/pow3(mri))*ri;
            }
        };
        vector unused;
        forAll(faceOwn, j)
        {
            if (faceOwn[j] < 0 || faceNei[j] < 0)
            {
                exact(faceOutAt[j], phiOut[j], gradOut[j]);
            }
        }
        forAll(bFaceRow, j)
        {
            exact(bFaceAt[j], phiB[j], unused);
        }

        // The shape's charge and the fixed values
        Eigen::VectorXd rhs0(Eigen::VectorXd::Zero(n));
        scalar wSum = 0;
        forAll(w, j)
        {
            wSum += w[j];
        }
        forAll(cells, j)
        {
            rhs0[local_[cells[j]]] += w[j]/wSum;
        }
        forAll(faceOwn, j)
        {
            const label l = faceOwn[j] < 0 ? faceNei[j] : faceOwn[j];
            if (faceOwn[j] < 0 || faceNei[j] < 0)
            {
                rhs0[l] += faceCoeff[j]*phiOut[j];
            }
        }
        forAll(bFaceRow, j)
        {
            rhs0[bFaceRow[j]] += bFaceCoeff[j]*phiB[j];
        }
        // Gauss linear gradient g of a potential p at the patch cells, with
        // the fixed values around (fixed) or zero there (the part linear
        // in p alone)
        const auto gaussGrad = [&](const Eigen::VectorXd& p, const bool fixed)
        {
            g = Zero;
            forAll(faceOwn, j)
            {
                const label lo = faceOwn[j], ln = faceNei[j];
                const scalar out = fixed ? phiOut[j] : 0;
                const scalar phiF =
                    faceWeight[j]*(lo >= 0 ? p[lo] : out)
                  + (1 - faceWeight[j])*(ln >= 0 ? p[ln] : out);
                if (lo >= 0)
                {
                    g[lo] += phiF*faceSf[j];
                }
                if (ln >= 0)
                {
                    g[ln] -= phiF*faceSf[j];
                }
            }
            if (fixed)
            {
                forAll(bFaceRow, j)
                {
                    g[bFaceRow[j]] += phiB[j]*bFaceSf[j];
                }
            }
            forAll(patchCells, i)
            {
                g[i] /= V[patchCells[i]];
            }
        };

        // The explicit non-orthogonal correction's flux (added to the
        // owner's Laplacian, taken from the neighbour's; the system is
        // negated) from the gradient g
        const auto correction = [&](const bool fixed)
        {
            Eigen::VectorXd c(Eigen::VectorXd::Zero(n));
            forAll(faceOwn, j)
            {
                const label lo = faceOwn[j], ln = faceNei[j];
                const vector out = fixed ? gradOut[j] : Zero;
                const vector gf =
                    faceWeight[j]*(lo >= 0 ? g[lo] : out)
                  + (1 - faceWeight[j])*(ln >= 0 ? g[ln] : out);
                const scalar flux =
                    eps_*faceMagSf[j]*(faceCorr[j] & gf);
                if (lo >= 0)
                {
                    c[lo] += flux;
                }
                if (ln >= 0)
                {
                    c[ln] -= flux;
                }
            }
            return c;
        };

        // With the correction, the potential solves M phi = rhs0 + C phi
        // + c0 (C linear in phi, c0 from the fixed values): meshPoisson's
        // correctors are the fixed-point iteration of
        // (I - M^-1 C) phi = M^-1 (rhs0 + c0), solved here by GMRES
        // (Saad & Schultz 1986) preconditioned by the factorisation, in
        // fewer solves. Hand-written: Eigen's GMRES (unsupported) takes an
        // assembled matrix, C is a matrix-free two-ring stencil
        Eigen::VectorXd phi;
        if (nNonOrthCorr_ == 0)
        {
            phi = ldlt.solve(rhs0);
        }
        else
        {
            gaussGrad(Eigen::VectorXd::Zero(n), true);
            phi = ldlt.solve(rhs0 + correction(true));
            const auto A = [&](const Eigen::VectorXd& v)
            {
                gaussGrad(v, false);
                return Eigen::VectorXd(v - ldlt.solve(correction(false)));
            };
            const Eigen::VectorXd Aphi(A(phi));
            // Residual of the start phi: M^-1 C phi
            Eigen::VectorXd r(phi - Aphi);
            const scalar beta = r.norm();
            const scalar target = tolerance_*phi.norm();
            if (beta > target)
            {
                const label kMax = nNonOrthCorr_;
                Eigen::MatrixXd Q(n, kMax + 1);
                Eigen::MatrixXd H(Eigen::MatrixXd::Zero(kMax + 1, kMax));
                Q.col(0) = r/beta;
                Eigen::VectorXd y;
                for (label k = 0; k < kMax; ++k)
                {
                    Eigen::VectorXd w(A(Q.col(k)));
                    for (label i = 0; i <= k; ++i)
                    {
                        H(i, k) = Q.col(i).dot(w);
                        w -= H(i, k)*Q.col(i);
                    }
                    H(k + 1, k) = w.norm();
                    Eigen::VectorXd e(Eigen::VectorXd::Zero(k + 2));
                    e[0] = beta;
                    const Eigen::MatrixXd Hk(H.topLeftCorner(k + 2, k + 1));
                    y = Hk.householderQr().solve(e);
                    if
                    (
                        (e - Hk*y).norm() < target
                     || H(k + 1, k) < 1e-14*beta
                     || k == kMax - 1
                    )
                    {
                        break;
                    }
                    Q.col(k + 1) = w/H(k + 1, k);
                }
                phi += Q.leftCols(y.size())*y;
            }
        }

        // The shape's average of -grad(Phi)
        gaussGrad(phi, true);
        forAll(cells, j)
        {
            result[s] -= w[j]*g[local_[cells[j]]];
        }
        result[s] /= wSum;
        if (imageSign != 0)
        {
            // Less the image's exact field: what is left is the mesh's
            // error on this local problem
            const vector ri(x - xImage);
            result[s] -= (imageSign*k/pow3(mag(ri)))*ri;
        }
    }

    forAll(patchCells, i)
    {
        local_[patchCells[i]] = -1;
    }
    return result;
}


// ************************************************************************* //
