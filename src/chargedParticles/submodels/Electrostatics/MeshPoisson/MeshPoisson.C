/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "MeshPoisson.H"
#include "inputLimits.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary& Foam::MeshPoisson<CloudType>::checkedCoeffs
(
    const dictionary& coeffs,
    const polyMesh& mesh
)
{
    const scalar diagonal = mag(mesh.bounds().span());
    for (const word key : {"radius", "rCut"})
    {
        scalar r = 0;
        if
        (
            coeffs.readIfPresent(key, r)
         && !(r >= inputLimits::sizeMin && r <= diagonal)
        )
        {
            FatalIOErrorInFunction(coeffs)
                << "Entry " << key << " = " << r << " in "
                << coeffs.name().c_str() << " is out of range: it must be"
                << " finite and > 0, in [" << inputLimits::sizeMin << ", "
                << diagonal << "] m (1 nm to the diagonal of the mesh's"
                << " bounding box)" << exit(FatalIOError);
        }
    }
    return coeffs;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::MeshPoisson<CloudType>::MeshPoisson
(
    const dictionary& dict,
    CloudType& owner
)
:
    CoulombElectrostatics<CloudType>(dict, owner, typeName),
    solver_
    (
        new meshPoisson
        (
            owner.mesh(),
            checkedCoeffs(this->coeffDict(), owner.mesh())
        )
    )
{
    if (this->appliedField().valid())
    {
        FatalIOErrorInFunction(dict)
            << "Entry appliedField in " << dict.name().c_str() << " does"
            << " not go with electrostaticsModel meshPoisson: the potential's"
            << " boundary conditions (electrodes) apply the field there"
            << exit(FatalIOError);
    }
}


template<class CloudType>
Foam::MeshPoisson<CloudType>::MeshPoisson
(
    const MeshPoisson<CloudType>& em
)
:
    CoulombElectrostatics<CloudType>(em),
    solver_(em.solver_)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::MeshPoisson<CloudType>::calculate()
{
    // All charges as the sources, and per processor (the contact
    // correction wants those)
    List<pointField> allX;
    List<scalarField> allQ;
    pointField xS;
    scalarField qS;
    label offset = 0;
    this->gatherCharges(allX, allQ, xS, qS, offset);

    // The cells of the local parcels, and for the cellCentroid correction
    // (Rasera Eq. 31 compares them) the centres of all parcels' cells
    const label n = this->owner().size();
    const bool centroids =
        solver_->correction() == meshPoisson::correctionType::cellCentroid;
    labelList cells(n);
    List<pointField> allC(Pstream::nProcs());
    pointField& c = allC[Pstream::myProcNo()];
    c.setSize(centroids ? n : 0);
    const volVectorField& C = this->owner().mesh().C();
    label i = 0;
    for (const auto& p : this->owner())
    {
        cells[i] = p.cell();
        if (centroids)
        {
            c[i] = C[p.cell()];
        }
        ++i;
    }
    pointField cS;
    if (centroids)
    {
        Pstream::gatherList(allC);
        Pstream::scatterList(allC);
        scalarField dummy;
        label o;
        this->combine(allC, allQ, cS, dummy, o);
    }

    // Mesh field at the parcels: interpolated (cellCentroid: their own tet
    // coordinates, no search; at the centre within the cell while lazy
    // tracking lets it drift) or averaged over their shapes (shaped, in
    // addNearField); then the near-field correction
    solver_->update(xS, qS, offset, cells);
    vectorField E(n);
    if (centroids)
    {
        const interpolation<vector>& EMesh = solver_->interpolator();
        i = 0;
        for (const auto& p : this->owner())
        {
            E[i++] =
                p.drift() == vector::zero
              ? EMesh.interpolate(p.coordinates(), p.currentTetIndices())
              : EMesh.interpolate(p.centre(), p.cell());
        }
    }
    else
    {
        // All of it from addNearField
        E = Zero;
    }
    solver_->addNearField
    (
        SubList<point>(xS, n, offset), offset, cS, E
    );

    this->setFields(allX, allQ, E);
}


// ************************************************************************* //
