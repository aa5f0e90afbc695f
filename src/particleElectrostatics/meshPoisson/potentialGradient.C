/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "potentialGradient.H"
#include "fvMatrices.H"
#include "fvcDiv.H"
#include "gaussGrad.H"
#include "gaussLaplacianScheme.H"
#include "linear.H"
#include "extrapolatedCalculatedFvPatchFields.H"
#include "syncTools.H"

// * * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::Enum<Foam::potentialGradient::schemeType>
Foam::potentialGradient::schemeTypeNames
({
    { schemeType::leastSquares, "leastSquares" },
    { schemeType::Gauss, "Gauss" },
});


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::potentialGradient::calcVectors()
{
    // As OpenFOAM's leastSquaresVectors::calcLeastSquaresVectors, with a
    // non-coupled boundary face weighted 1/2 (the mirror of an internal
    // face: class description)
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    const vectorField& C = mesh_.C().primitiveField();
    const surfaceScalarField& w = mesh_.weights();
    const surfaceScalarField& magSf = mesh_.magSf();
    const label nInternal = mesh_.nInternalFaces();

    const auto boundaryWeight = [&](const label patchi, const label i)
    {
        const fvsPatchScalarField& pw = w.boundaryField()[patchi];
        return pw.coupled() ? 1 - pw[i] : 0.5;
    };

    symmTensorField dd(mesh_.nCells(), Zero);
    forAll(owner, f)
    {
        const vector d(C[neighbour[f]] - C[owner[f]]);
        const symmTensor wdd((magSf[f]/magSqr(d))*sqr(d));
        dd[owner[f]] += (1 - w[f])*wdd;
        dd[neighbour[f]] += w[f]*wdd;
    }
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const vectorField pd(p.delta());
        const scalarField& pMagSf = magSf.boundaryField()[patchi];
        forAll(pd, i)
        {
            const vector& d = pd[i];
            dd[p.faceCells()[i]] +=
                (boundaryWeight(patchi, i)*pMagSf[i]/magSqr(d))*sqr(d);
        }
    }
    const symmTensorField invDd(inv(dd));

    ownVectors_.setSize(nInternal);
    neiVectors_.setSize(nInternal);
    forAll(owner, f)
    {
        const vector d(C[neighbour[f]] - C[owner[f]]);
        const scalar a = magSf[f]/magSqr(d);
        ownVectors_[f] = (1 - w[f])*a*(invDd[owner[f]] & d);
        neiVectors_[f] = -w[f]*a*(invDd[neighbour[f]] & d);
    }
    boundaryVectors_.setSize(mesh_.nFaces() - nInternal, Zero);
    forAll(mesh_.boundary(), patchi)
    {
        const fvPatch& p = mesh_.boundary()[patchi];
        const vectorField pd(p.delta());
        const scalarField& pMagSf = magSf.boundaryField()[patchi];
        const label start = p.start() - nInternal;
        forAll(pd, i)
        {
            const vector& d = pd[i];
            boundaryVectors_[start + i] =
                (boundaryWeight(patchi, i)*pMagSf[i]/magSqr(d))
               *(invDd[p.faceCells()[i]] & d);
        }
    }
    boundaryNeighbourVectors_ = boundaryVectors_;
    syncTools::swapBoundaryFaceList(mesh_, boundaryNeighbourVectors_);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::potentialGradient::potentialGradient
(
    const fvMesh& mesh,
    const schemeType scheme
)
:
    mesh_(mesh),
    scheme_(scheme)
{
    if (leastSquares())
    {
        calcVectors();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::tmp<Foam::volVectorField> Foam::potentialGradient::grad
(
    const volScalarField& Phi
) const
{
    const word name("grad(" + Phi.name() + ')');
    if (!leastSquares())
    {
        return fv::gaussGrad<scalar>(mesh_).grad(Phi, name);
    }

    tmp<volVectorField> tg
    (
        new volVectorField
        (
            IOobject(name, Phi.instance(), mesh_),
            mesh_,
            dimensionedVector(Phi.dimensions()/dimLength, Zero),
            extrapolatedCalculatedFvPatchVectorField::typeName
        )
    );
    volVectorField& g = tg.ref();
    vectorField& gi = g.primitiveFieldRef();
    const scalarField& p = Phi.primitiveField();
    const labelUList& owner = mesh_.owner();
    const labelUList& neighbour = mesh_.neighbour();
    forAll(owner, f)
    {
        const scalar delta = p[neighbour[f]] - p[owner[f]];
        gi[owner[f]] += ownVectors_[f]*delta;
        gi[neighbour[f]] -= neiVectors_[f]*delta;
    }
    forAll(Phi.boundaryField(), patchi)
    {
        const fvPatchScalarField& pf = Phi.boundaryField()[patchi];
        const labelUList& faceCells = pf.patch().faceCells();
        const scalarField values
        (
            pf.coupled() ? pf.patchNeighbourField() : tmp<scalarField>(pf)
        );
        const label start = pf.patch().start() - mesh_.nInternalFaces();
        forAll(values, i)
        {
            gi[faceCells[i]] +=
                boundaryVectors_[start + i]*(values[i] - p[faceCells[i]]);
        }
    }
    g.correctBoundaryConditions();
    fv::gaussGrad<scalar>::correctBoundaryConditions(Phi, g);
    return tg;
}


Foam::tmp<Foam::fvScalarMatrix> Foam::potentialGradient::laplacian
(
    const dimensionedScalar& eps,
    const volScalarField& Phi
) const
{
    const surfaceScalarField epsMagSf(eps*mesh_.magSf());
    tmp<fvScalarMatrix> tL
    (
        fv::gaussLaplacianScheme<scalar, scalar>::fvmLaplacianUncorrected
        (
            epsMagSf, mesh_.nonOrthDeltaCoeffs(), Phi
        )
    );
    // The explicit correction (correctedSnGrad::fullGradCorrection)
    tL.ref() += fvc::div
    (
        epsMagSf
       *linear<vector>(mesh_).dotInterpolate
        (
            mesh_.nonOrthCorrectionVectors(), grad(Phi)
        )
    );
    return tL;
}


// ************************************************************************* //
