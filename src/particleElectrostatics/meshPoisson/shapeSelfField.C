/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "shapeSelfField.H"
#include "pairwiseCoulomb.H"
#include "s2Shape.H"
#include "emptyFvPatch.H"
#include "cyclicFvPatch.H"
#include "surfaceFields.H"
#include "processorPolyPatch.H"
#include "Map.H"
#include "UIndirectList.H"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <Eigen/MetisSupport>
#include <Eigen/QR>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::shapeSelfField::shapeSelfField
(
    const fvMesh& mesh,
    const potentialGradient& gradient,
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
    gradient_(gradient),
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
    return uniformAmong(cells, mesh_.V()[c]);
}


bool Foam::shapeSelfField::uniformAmong
(
    const UList<label>& cells,
    const scalar Vref
) const
{
    const scalarField& V = mesh_.V().field();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceVectorField& corr = mesh_.nonOrthCorrectionVectors();
    const label nInternal = mesh_.nInternalFaces();
    const scalar tol = 1e-6;
    for (const label ci : cells)
    {
        if (mag(V[ci] - Vref) > tol*Vref)
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
    const label c,
    scalar* largest
) const
{
    vector valueC(Zero);
    scalar largestHere = 0;
    const labelList& cPoints = mesh_.cellPoints()[c];
    for (const label pointi : cPoints)
    {
        valueC += pointField_[pointi];
        largestHere = max(largestHere, mag(pointField_[pointi]));
    }
    valueC /= cPoints.size();
    if (largest)
    {
        *largest = largestHere;
    }

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

namespace
{

using namespace Foam;

typedef Eigen::SimplicialLDLT
<
    Eigen::SparseMatrix<double>,
    Eigen::Lower,
    Eigen::MetisOrdering<int>
> patchFactorisation;


//- The fixed values around a patch for one charge: the exact potential
//  per unit charge at the cells around it (and its gradient) and at the
//  boundary points
struct patchValues
{
    scalarField phiOut, phiB;
    vectorField gradOut;
};


//- The negated Laplacian of a patch (symmetric positive definite)
template<class System>
Eigen::SparseMatrix<double> patchMatrix(const System& sys)
{
    const label n = sys.V.size();
    std::vector<Eigen::Triplet<double>> triplets;
    triplets.reserve(2*sys.own.size() + n);
    scalarField diag(n, 0);
    forAll(sys.own, j)
    {
        const scalar a = sys.coeff[j];
        const label lo = sys.own[j], ln = sys.nei[j];
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
    forAll(sys.bRow, j)
    {
        diag[sys.bRow[j]] += sys.bCoeff[j];
    }
    forAll(diag, i)
    {
        triplets.emplace_back(i, i, diag[i]);
    }
    Eigen::SparseMatrix<double> M(n, n);
    M.setFromTriplets(triplets.begin(), triplets.end());
    return M;
}


//- The exact potential per unit charge (and its gradient) at the cells
//  around the patch and at the boundary points: the sources of the local
//  problem lp in free space, S2 shapes of radius R (a wall face within R
//  of one holds the shape's potential, which the mesh's deposit
//  approximates, not a point's); k the Coulomb constant
template<class System>
void exactValues
(
    const System& sys,
    const shapeSelfField::localProblem& lp,
    const scalar R,
    const scalar k,
    patchValues& out
)
{
    const auto exact = [&](const point& y, scalar& phiY, vector& gradY)
    {
        phiY = 0;
        gradY = Zero;
        forAll(lp.x, a)
        {
            scalar phiA;
            vector gradA;
            s2Shape::potential(k*lp.q[a], R, y - lp.x[a], phiA, gradA);
            phiY += phiA;
            gradY += gradA;
        }
    };
    vector unused;
    forAll(sys.own, j)
    {
        if (sys.own[j] < 0 || sys.nei[j] < 0)
        {
            exact(sys.outAt[j], out.phiOut[j], out.gradOut[j]);
        }
    }
    forAll(sys.bRow, j)
    {
        exact(sys.bAt[j], out.phiB[j], unused);
    }
}


//- The gradient g of a potential p at the patch's rows (the mesh's:
//  least squares, or Gauss linear where the system has no least-squares
//  vectors), with the fixed values around (fixed) or zero there (the part
//  linear in p alone)
template<class System>
void patchGrad
(
    const System& sys,
    const patchValues& out,
    const Eigen::VectorXd& p,
    const bool fixed,
    vectorField& g
)
{
    g = Zero;
    if (sys.lsOwn.size())
    {
        forAll(sys.own, j)
        {
            const label lo = sys.own[j], ln = sys.nei[j];
            const scalar o = fixed ? out.phiOut[j] : 0;
            const scalar delta =
                (ln >= 0 ? p[ln] : o) - (lo >= 0 ? p[lo] : o);
            if (lo >= 0)
            {
                g[lo] += sys.lsOwn[j]*delta;
            }
            if (ln >= 0)
            {
                g[ln] -= sys.lsNei[j]*delta;
            }
        }
        forAll(sys.bRow, j)
        {
            const label r = sys.bRow[j];
            g[r] += sys.bLs[j]*((fixed ? out.phiB[j] : 0) - p[r]);
        }
        return;
    }
    forAll(sys.own, j)
    {
        const label lo = sys.own[j], ln = sys.nei[j];
        const scalar o = fixed ? out.phiOut[j] : 0;
        const scalar phiF =
            sys.weight[j]*(lo >= 0 ? p[lo] : o)
          + (1 - sys.weight[j])*(ln >= 0 ? p[ln] : o);
        if (lo >= 0)
        {
            g[lo] += phiF*sys.Sf[j];
        }
        if (ln >= 0)
        {
            g[ln] -= phiF*sys.Sf[j];
        }
    }
    if (fixed)
    {
        forAll(sys.bRow, j)
        {
            g[sys.bRow[j]] += out.phiB[j]*sys.bSf[j];
        }
    }
    forAll(g, i)
    {
        g[i] /= sys.V[i];
    }
}


//- The explicit non-orthogonal correction's flux (added to the owner's
//  Laplacian, taken from the neighbour's; the system is negated) from the
//  gradient g, with the exact gradients around (fixed) or zero there
template<class System>
Eigen::VectorXd nonOrthCorrection
(
    const System& sys,
    const patchValues& out,
    const vectorField& g,
    const scalar eps,
    const bool fixed
)
{
    Eigen::VectorXd c(Eigen::VectorXd::Zero(g.size()));
    forAll(sys.own, j)
    {
        const label lo = sys.own[j], ln = sys.nei[j];
        const vector o = fixed ? out.gradOut[j] : Zero;
        const vector gf =
            sys.weight[j]*(lo >= 0 ? g[lo] : o)
          + (1 - sys.weight[j])*(ln >= 0 ? g[ln] : o);
        const scalar flux = eps*sys.magSf[j]*(sys.corr[j] & gf);
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
}


//- GMRES (Saad & Schultz 1986) for applyA(phi) = phi0, phi0 the start
//  (phi in; the solution out), at most kMax iterations, to a residual of
//  tolerance |phi0|. Hand-written: Eigen's GMRES (unsupported) takes an
//  assembled matrix, the operator here is matrix-free
template<class Operator>
void gmres
(
    const Operator& applyA,
    Eigen::VectorXd& phi,
    const label kMax,
    const scalar tolerance
)
{
    const Eigen::VectorXd Aphi(applyA(phi));
    // Residual of the start phi: M^-1 C phi
    Eigen::VectorXd r(phi - Aphi);
    const scalar beta = r.norm();
    const scalar target = tolerance*phi.norm();
    if (!(beta > target))
    {
        return;
    }
    const label n = phi.size();
    Eigen::MatrixXd Q(n, kMax + 1);
    Eigen::MatrixXd H(Eigen::MatrixXd::Zero(kMax + 1, kMax));
    Q.col(0) = r/beta;
    Eigen::VectorXd y;
    for (label k = 0; k < kMax; ++k)
    {
        Eigen::VectorXd w(applyA(Q.col(k)));
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

} // End anonymous namespace


Foam::shapeSelfField::patchSystem Foam::shapeSelfField::assemblePatch
(
    const UList<label>& patchCells,
    const UList<vector>& patchShifts,
    DynamicList<label>* bFaceOf
) const
{
    const scalarField& V = mesh_.V().field();
    const vectorField& C = mesh_.C().primitiveField();
    const labelUList& own = mesh_.owner();
    const labelUList& nei = mesh_.neighbour();
    const label nInternal = mesh_.nInternalFaces();
    const surfaceScalarField& weights = mesh_.weights();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceVectorField& corrVec = mesh_.nonOrthCorrectionVectors();
    const bool ls = gradient_.leastSquares();

    patchSystem sys;
    sys.V.setSize(patchCells.size());
    forAll(patchCells, i)
    {
        sys.V[i] = V[patchCells[i]];
    }
    // Internal faces and cyclic faces between two patch cells (from the
    // owner patch's side), and boundary faces with a fixed value
    forAll(patchCells, i)
    {
        const label c = patchCells[i];
        const vector& shift = patchShifts[i];
        for (const label f : mesh_.cells()[c])
        {
            if (f >= nInternal)
            {
                addBoundaryFace(sys, i, c, f, shift, patchShifts, bFaceOf);
                continue;
            }
            const label lo = local_[own[f]];
            const label ln = local_[nei[f]];
            // Once: from the owner's side, or from a patch neighbour whose
            // owner lies outside
            if ((own[f] == c) || lo < 0)
            {
                const label o = lo < 0 ? own[f] : nei[f];
                sys.addFace
                (
                    ls, lo, ln, internalCoeff_[f], weights[f], Sf[f],
                    magSf[f], corrVec[f], C[o] + shift,
                    ls ? gradient_.ownVector(f) : Zero,
                    ls ? gradient_.neiVector(f) : Zero
                );
            }
        }
    }
    return sys;
}


void Foam::shapeSelfField::addBoundaryFace
(
    patchSystem& sys,
    const label i,
    const label c,
    const label f,
    const vector& shift,
    const UList<vector>& patchShifts,
    DynamicList<label>* bFaceOf
) const
{
    const vectorField& C = mesh_.C().primitiveField();
    const surfaceScalarField& weights = mesh_.weights();
    const surfaceVectorField& Sf = mesh_.Sf();
    const surfaceScalarField& magSf = mesh_.magSf();
    const surfaceVectorField& corrVec = mesh_.nonOrthCorrectionVectors();
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const bool ls = gradient_.leastSquares();

    const label patchi = pbm.whichPatch(f);
    const label facei = f - pbm[patchi].start();
    const scalar b = boundaryCoeff_[patchi][facei];
    if (!(b > 0))
    {
        return;
    }
    // The neighbour's centre across a coupled face (else the face
    // centre), in the patch's unfolded frame
    const point at(boundaryPoint_[patchi][facei] + shift);
    const cyclicFvPatch* cyc = isA<cyclicFvPatch>(mesh_.boundary()[patchi]);
    if (cyc)
    {
        // Across a cyclic patch to a patch cell that the unfolded frame
        // puts there: a face between two unknowns
        const label cn = cyc->neighbFvPatch().faceCells()[facei];
        const label ln = local_[cn];
        const scalar delta = mag(at - C[c] - shift);
        if (ln >= 0 && mag(C[cn] + patchShifts[ln] - at) < 1e-6*delta)
        {
            if (cyc->owner())
            {
                sys.addFace
                (
                    ls, i, ln, b,
                    weights.boundaryField()[patchi][facei],
                    Sf.boundaryField()[patchi][facei],
                    magSf.boundaryField()[patchi][facei],
                    corrVec.boundaryField()[patchi][facei],
                    point::zero,
                    ls ? gradient_.boundaryVector(f) : Zero,
                    ls ? gradient_.boundaryNeighbourVector(f) : Zero
                );
            }
            return;
        }
    }
    if (bFaceOf)
    {
        bFaceOf->append(f);
    }
    sys.bRow.append(i);
    sys.bAt.append(at);
    sys.bSf.append(Sf.boundaryField()[patchi][facei]);
    sys.bCoeff.append(b);
    if (ls)
    {
        sys.bLs.append(gradient_.boundaryVector(f));
    }
}


Foam::shapeSelfField::localProblem Foam::shapeSelfField::pointProblem
(
    const point& x,
    const labelUList& rows,
    const UList<scalar>& weights,
    const point& wallPoint,
    const vector& wallNormal,
    const scalar imageSign
) const
{
    localProblem lp;
    lp.x.setSize(1, x);
    lp.q.setSize(1, 1);
    lp.T.setSize(1, tensor::I);
    lp.rows = rows;
    lp.w = weights;
    lp.src.setSize(rows.size(), 0);
    lp.exact = Zero;

    // A point in the wall's plane (to round-off of its distance from the
    // origin) coincides with its image: the pair is no image problem (an
    // odd one has no charge, and the exact field of an even one is
    // singular), the point's own field is kept
    const scalar h = (x - wallPoint) & wallNormal;
    if (imageSign != 0 && mag(h) > 1e-12*mag(x - wallPoint) + VSMALL)
    {
        // The image in the wall's plane, its exact field on the shape
        // subtracted (the S2 pair's: see Description)
        const point xImage(x - 2*h*wallNormal);
        lp.x.append(xImage);
        lp.q.append(imageSign);
        lp.T.append(tensor::I - 2*sqr(wallNormal));
        lp.exact = imageSign*s2Shape::pairField(k_, shapeRadius_, x - xImage);
    }
    return lp;
}


Foam::vector Foam::shapeSelfField::solveProblem
(
    const UList<label>& patchCells,
    const UList<vector>& patchShifts,
    const localProblem& lp
) const
{
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = i;
    }
    List<localProblem> problems(1, lp);
    labelList& rows = problems[0].rows;
    bool inPatch = true;
    for (label& r : rows)
    {
        r = local_[r];
        inPatch = inPatch && r >= 0 && magSqr(patchShifts[r]) == 0;
    }
    vector result(Zero);
    if (inPatch)
    {
        result = solvePatch(assemblePatch(patchCells, patchShifts), problems)[0];
    }
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = -1;
    }
    return result;
}


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
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = i;
    }
    const patchSystem sys(assemblePatch(patchCells, patchShifts));
    List<labelList> shapeRows(xs.size());
    forAll(xs, s)
    {
        shapeRows[s].setSize(shapeCells[s].size());
        forAll(shapeCells[s], j)
        {
            shapeRows[s][j] = local_[shapeCells[s][j]];
        }
    }
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = -1;
    }
    List<localProblem> problems(xs.size());
    forAll(xs, s)
    {
        problems[s] = pointProblem
        (
            xs[s], shapeRows[s], shapeWeights[s],
            wallPoint, wallNormal, imageSign
        );
    }
    return solvePatch(sys, problems);
}


Foam::List<Foam::vector> Foam::shapeSelfField::solvePairs
(
    const UList<label>& patchCells,
    const UList<vector>& patchShifts,
    const point& x,
    const UList<label>& targetCells,
    const UList<scalar>& targetWeights,
    const UList<point>& xSources,
    const UList<DynamicList<label>>& sourceCells,
    const UList<DynamicList<scalar>>& sourceWeights,
    const UList<vector>& exactPair,
    const point& wallPoint,
    const vector& wallNormal,
    const scalar imageSign,
    vector* self
) const
{
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = i;
    }
    // Each shape's rows, empty where it does not lie within the patch
    const auto toRows = [&](const UList<label>& cells)
    {
        labelList rows(cells.size());
        forAll(cells, j)
        {
            rows[j] = local_[cells[j]];
            if (rows[j] < 0)
            {
                return labelList();
            }
        }
        return rows;
    };
    const labelList targetRows(toRows(targetCells));
    List<labelList> sourceRows(xSources.size());
    List<scalarField> w(xSources.size());
    forAll(xSources, s)
    {
        sourceRows[s] = toRows(sourceCells[s]);
        w[s] = sourceWeights[s];
    }
    List<vector> result(xSources.size(), Zero);
    if (targetRows.size())
    {
        result = solvePairRows
        (
            assemblePatch(patchCells, patchShifts), x, targetRows,
            targetWeights, xSources, sourceRows, w, exactPair,
            wallPoint, wallNormal, imageSign, self
        );
    }
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = -1;
    }
    return result;
}


Foam::List<Foam::vector> Foam::shapeSelfField::solvePairRows
(
    const patchSystem& sys,
    const point& x,
    const labelUList& targetRows,
    const UList<scalar>& targetWeights,
    const UList<point>& xSources,
    const UList<labelList>& sourceRows,
    const UList<scalarField>& sourceWeights,
    const UList<vector>& exactPair,
    const point& wallPoint,
    const vector& wallNormal,
    const scalar imageSign,
    vector* self
) const
{
    List<localProblem> problems(xSources.size() + 1);
    DynamicList<label> solved;
    forAll(xSources, s)
    {
        if (sourceRows[s].empty())
        {
            continue;
        }
        localProblem& lp = problems[solved.size()];
        lp = pointProblem
        (
            xSources[s], sourceRows[s], sourceWeights[s],
            wallPoint, wallNormal, imageSign
        );
        lp.exact = exactPair[s];
        if (lp.x.size() > 1)
        {
            // The image's field at the target: the average of a field
            // harmonic within the target's S2 shape is its value at the
            // centre
            const vector r(x - lp.x[1]);
            lp.exact += (lp.q[1]*k_/pow3(mag(r)))*r;
        }
        lp.targetRows = targetRows;
        lp.targetW = targetWeights;
        solved.append(s);
    }
    if (self)
    {
        problems[solved.size()] = pointProblem
        (
            x, targetRows, targetWeights, wallPoint, wallNormal, imageSign
        );
        problems.setSize(solved.size() + 1);
    }
    else
    {
        problems.setSize(solved.size());
    }
    List<vector> result(xSources.size(), Zero);
    if (problems.size())
    {
        const List<vector> errors(solvePatch(sys, problems));
        forAll(solved, j)
        {
            result[solved[j]] = errors[j];
        }
        if (self)
        {
            *self = errors.last();
        }
    }
    return result;
}


Foam::List<Foam::vector> Foam::shapeSelfField::solvePatch
(
    const patchSystem& sys,
    const UList<localProblem>& problems
) const
{
    const label n = sys.V.size();
    const scalar k = k_;

    // The matrix (negated: symmetric positive definite), factorised once
    // for every shape
    const Eigen::SparseMatrix<double> M(patchMatrix(sys));
    // METIS nested dissection instead of Eigen's default AMD ordering: less
    // fill on these 3-D patches, so the factorisation (most of the self
    // field's cost) runs about 1.5x faster with the same result
    const patchFactorisation ldlt(M);

    List<vector> result(problems.size(), Zero);
    patchValues out;
    out.phiOut.setSize(sys.own.size());
    out.gradOut.setSize(sys.own.size());
    out.phiB.setSize(sys.bRow.size());
    vectorField g(n);
    forAll(problems, s)
    {
        const localProblem& lp = problems[s];
        const labelUList& rows = lp.rows;
        const UList<scalar>& w = lp.w;
        exactValues(sys, lp, shapeRadius_, k, out);

        // The shapes' charges and the fixed values
        Eigen::VectorXd rhs0(Eigen::VectorXd::Zero(n));
        scalar wSum = 0;
        forAll(w, j)
        {
            wSum += w[j];
        }
        forAll(rows, j)
        {
            rhs0[rows[j]] += lp.q[lp.src[j]]*w[j]/wSum;
        }
        forAll(sys.own, j)
        {
            const label l = sys.own[j] < 0 ? sys.nei[j] : sys.own[j];
            if (sys.own[j] < 0 || sys.nei[j] < 0)
            {
                rhs0[l] += sys.coeff[j]*out.phiOut[j];
            }
        }
        forAll(sys.bRow, j)
        {
            rhs0[sys.bRow[j]] += sys.bCoeff[j]*out.phiB[j];
        }

        // With the correction, the potential solves M phi = rhs0 + C phi
        // + c0 (C linear in phi, c0 from the fixed values): meshPoisson's
        // correctors are the fixed-point iteration of
        // (I - M^-1 C) phi = M^-1 (rhs0 + c0), solved by GMRES
        // preconditioned by the factorisation, in fewer solves
        Eigen::VectorXd phi;
        if (nNonOrthCorr_ == 0)
        {
            phi = ldlt.solve(rhs0);
        }
        else
        {
            patchGrad(sys, out, Eigen::VectorXd::Zero(n), true, g);
            phi = ldlt.solve(rhs0 + nonOrthCorrection(sys, out, g, eps_, true));
            const auto A = [&](const Eigen::VectorXd& v)
            {
                patchGrad(sys, out, v, false, g);
                return Eigen::VectorXd
                (
                    v - ldlt.solve(nonOrthCorrection(sys, out, g, eps_, false))
                );
            };
            gmres(A, phi, nNonOrthCorr_, tolerance_);
        }

        // The average of -grad(Phi) over the charge's shape: a part from
        // an image's cells is mapped back (sign T^T E, as
        // meshPoisson::averageOverShapes); less the exact field of the
        // local problem, what is left is the mesh's error on it
        patchGrad(sys, out, phi, true, g);
        if (lp.targetRows.size())
        {
            // A pair's: over the target's shape (whole, no images)
            forAll(lp.targetRows, j)
            {
                result[s] -= lp.targetW[j]*g[lp.targetRows[j]];
            }
            result[s] /= sum(lp.targetW);
        }
        else
        {
            forAll(rows, j)
            {
                const label a = lp.src[j];
                const vector wg(w[j]*g[rows[j]]);
                result[s] -= a == 0 ? wg : lp.q[a]*(lp.T[a].T() & wg);
            }
            result[s] /= wSum;
        }
        result[s] -= lp.exact;
    }
    return result;
}


bool Foam::shapeSelfField::uniform() const
{
    return
        mesh_.nCells() == 0
     || uniformAmong(identity(mesh_.nCells()), mesh_.V()[0]);
}


Foam::shapeSelfField::patchPart Foam::shapeSelfField::part
(
    const UList<label>& patchCells,
    const UList<vector>& patchShifts,
    const UList<label>& shapeCells,
    const UList<scalar>& shapeWeights,
    const point& x,
    const scalar reach,
    const scalar Vref,
    const labelUList& cellGid,
    const labelUList& neighbourGid
) const
{
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = i;
    }
    DynamicList<label> bFaceOf;
    patchPart p;
    p.sys = assemblePatch(patchCells, patchShifts, &bFaceOf);
    forAll(patchCells, i)
    {
        local_[patchCells[i]] = -1;
    }
    p.uniform = uniformAmong(patchCells, Vref);
    p.cells = UIndirectList<label>(cellGid, patchCells)();
    p.shapeCells = UIndirectList<label>(cellGid, shapeCells)();
    p.shapeWeights = shapeWeights;

    // Rows named by their cells' global ids
    patchSystem& sys = p.sys;
    for (label& row : sys.own)
    {
        row = row < 0 ? -1 : p.cells[row];
    }
    for (label& row : sys.nei)
    {
        row = row < 0 ? -1 : p.cells[row];
    }

    // Faces on processor patches: to a cell of the patch on the other side
    // (once, from the side of the smaller id) or to a cell around it, with
    // the exact value at its centre, as an internal face of a serial mesh
    // would be; the other boundary faces keep their fixed values
    const polyBoundaryMesh& pbm = mesh_.boundaryMesh();
    const label nInternal = mesh_.nInternalFaces();
    label nb = 0;
    forAll(sys.bRow, j)
    {
        const label f = bFaceOf[j];
        const label patchi = pbm.whichPatch(f);
        const label me = p.cells[sys.bRow[j]];
        if (!isA<processorPolyPatch>(pbm[patchi]))
        {
            sys.bRow[nb] = me;
            sys.bAt[nb] = sys.bAt[j];
            sys.bSf[nb] = sys.bSf[j];
            sys.bCoeff[nb] = sys.bCoeff[j];
            if (gradient_.leastSquares())
            {
                sys.bLs[nb] = sys.bLs[j];
            }
            ++nb;
            continue;
        }
        const label facei = f - pbm[patchi].start();
        const label other = neighbourGid[f - nInternal];
        const bool inPatch = magSqr(sys.bAt[j] - x) < reach*reach;
        if (inPatch && me > other)
        {
            continue;
        }
        sys.own.append(me);
        sys.nei.append(inPatch ? other : -1);
        sys.coeff.append(sys.bCoeff[j]);
        sys.weight.append(mesh_.weights().boundaryField()[patchi][facei]);
        sys.magSf.append(mesh_.magSf().boundaryField()[patchi][facei]);
        sys.Sf.append(sys.bSf[j]);
        sys.corr.append
        (
            mesh_.nonOrthCorrectionVectors().boundaryField()[patchi][facei]
        );
        sys.outAt.append(sys.bAt[j]);
        if (gradient_.leastSquares())
        {
            sys.lsOwn.append(gradient_.boundaryVector(f));
            sys.lsNei.append(gradient_.boundaryNeighbourVector(f));
        }
    }
    sys.bRow.setSize(nb);
    sys.bAt.setSize(nb);
    sys.bSf.setSize(nb);
    sys.bCoeff.setSize(nb);
    if (gradient_.leastSquares())
    {
        sys.bLs.setSize(nb);
    }
    return p;
}


bool Foam::shapeSelfField::mergeParts
(
    const UList<patchPart>& parts,
    patchSystem& sys,
    Map<label>& row
) const
{
    bool uniform = true;
    label n = 0;
    for (const patchPart& p : parts)
    {
        uniform = uniform && p.uniform;
        n += p.cells.size();
    }
    // One row per cell, in the parts' order
    row.clear();
    row.resize(2*n);
    sys.V.setSize(n);
    n = 0;
    for (const patchPart& p : parts)
    {
        forAll(p.cells, i)
        {
            if (row.insert(p.cells[i], n))
            {
                sys.V[n++] = p.sys.V[i];
            }
        }
    }
    sys.V.setSize(n);
    const auto rowOf = [&](const label g)
    {
        const auto iter = row.cfind(g);
        return g < 0 || !iter.found() ? -1 : *iter;
    };
    for (const patchPart& p : parts)
    {
        const patchSystem& ps = p.sys;
        forAll(ps.own, j)
        {
            const label lo = rowOf(ps.own[j]);
            const label ln = rowOf(ps.nei[j]);
            if (lo < 0 && ln < 0)
            {
                continue;
            }
            sys.own.append(lo);
            sys.nei.append(ln);
            sys.coeff.append(ps.coeff[j]);
            sys.weight.append(ps.weight[j]);
            sys.magSf.append(ps.magSf[j]);
            sys.Sf.append(ps.Sf[j]);
            sys.corr.append(ps.corr[j]);
            sys.outAt.append(ps.outAt[j]);
            if (ps.lsOwn.size())
            {
                sys.lsOwn.append(ps.lsOwn[j]);
                sys.lsNei.append(ps.lsNei[j]);
            }
        }
        forAll(ps.bRow, j)
        {
            sys.bRow.append(rowOf(ps.bRow[j]));
            sys.bAt.append(ps.bAt[j]);
            sys.bSf.append(ps.bSf[j]);
            sys.bCoeff.append(ps.bCoeff[j]);
            if (ps.bLs.size())
            {
                sys.bLs.append(ps.bLs[j]);
            }
        }
    }
    return uniform;
}


namespace
{

//- The rows and weights of a shape's parts (cells as global ids; false if
//  a cell has no row)
bool shapeRows
(
    const Foam::Map<Foam::label>& row,
    const Foam::UList<Foam::labelList>& cells,
    const Foam::UList<Foam::scalarField>& weights,
    Foam::DynamicList<Foam::label>& rows,
    Foam::DynamicList<Foam::scalar>& w
)
{
    forAll(cells, k)
    {
        forAll(cells[k], j)
        {
            const auto iter = row.cfind(cells[k][j]);
            if (!iter.found())
            {
                return false;
            }
            rows.append(*iter);
            w.append(weights[k][j]);
        }
    }
    return true;
}

}


Foam::vector Foam::shapeSelfField::solveParts
(
    const UList<patchPart>& parts,
    const point& x,
    const point& wallPoint,
    const vector& wallNormal,
    const scalar imageSign
) const
{
    patchSystem sys;
    Map<label> row;
    if (mergeParts(parts, sys, row) || sys.V.empty())
    {
        return Zero;
    }
    DynamicList<label> rows;
    DynamicList<scalar> w;
    for (const patchPart& p : parts)
    {
        forAll(p.shapeCells, j)
        {
            const auto iter = row.cfind(p.shapeCells[j]);
            if (iter.found())
            {
                rows.append(*iter);
                w.append(p.shapeWeights[j]);
            }
        }
    }
    return solvePatch
    (
        sys,
        List<localProblem>
        (
            1, pointProblem(x, rows, w, wallPoint, wallNormal, imageSign)
        )
    )[0];
}


Foam::List<Foam::vector> Foam::shapeSelfField::solvePairParts
(
    const UList<patchPart>& parts,
    const point& x,
    const UList<point>& xSources,
    const UList<vector>& exactPair,
    const point& wallPoint,
    const vector& wallNormal,
    const scalar imageSign,
    vector* self
) const
{
    // The mesh's pair field has the truncation error on uniform meshes too:
    // solved whatever the parts' uniformity
    patchSystem sys;
    Map<label> row;
    mergeParts(parts, sys, row);
    List<labelList> cells(parts.size());
    List<scalarField> weights(parts.size());
    forAll(parts, k)
    {
        cells[k] = parts[k].shapeCells;
        weights[k] = parts[k].shapeWeights;
    }
    DynamicList<label> targetRows;
    DynamicList<scalar> targetW;
    if (sys.V.empty() || !shapeRows(row, cells, weights, targetRows, targetW))
    {
        return List<vector>(xSources.size(), Zero);
    }
    List<labelList> sourceRows(xSources.size());
    List<scalarField> sourceW(xSources.size());
    forAll(xSources, s)
    {
        forAll(parts, k)
        {
            cells[k] = parts[k].sourceCells[s];
            weights[k] = parts[k].sourceWeights[s];
        }
        DynamicList<label> rows;
        DynamicList<scalar> w;
        if (shapeRows(row, cells, weights, rows, w))
        {
            sourceRows[s].transfer(rows);
            sourceW[s].transfer(w);
        }
    }
    return solvePairRows
    (
        sys, x, targetRows, targetW, xSources, sourceRows, sourceW,
        exactPair, wallPoint, wallNormal, imageSign, self
    );
}


Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const shapeSelfField::patchPart& p
)
{
    const shapeSelfField::patchSystem& s = p.sys;
    os  << p.cells << s.V << s.own << s.nei << s.coeff << s.weight
        << s.magSf << s.Sf << s.corr << s.outAt << s.bRow << s.bAt << s.bSf
        << s.bCoeff << s.lsOwn << s.lsNei << s.bLs << p.shapeCells << p.shapeWeights << p.uniform
        << p.sourceCells << p.sourceWeights;
    return os;
}


Foam::Istream& Foam::operator>>(Istream& is, shapeSelfField::patchPart& p)
{
    shapeSelfField::patchSystem& s = p.sys;
    is  >> p.cells >> s.V >> s.own >> s.nei >> s.coeff >> s.weight
        >> s.magSf >> s.Sf >> s.corr >> s.outAt >> s.bRow >> s.bAt >> s.bSf
        >> s.bCoeff >> s.lsOwn >> s.lsNei >> s.bLs >> p.shapeCells >> p.shapeWeights >> p.uniform
        >> p.sourceCells >> p.sourceWeights;
    return is;
}


// ************************************************************************* //
