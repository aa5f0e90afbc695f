/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "MeshPoisson.H"
#include "inputLimits.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
const Foam::dictionary& Foam::MeshPoisson<CloudType>::checkedCoeffs
(
    const dictionary& coeffs,
    const polyMesh& mesh
)
{
    const scalar diagonal = mag(mesh.bounds().span());
    const std::string range
    (
        ": it must be finite and > 0, in [" + Foam::name(inputLimits::sizeMin)
      + ", " + Foam::name(diagonal) + "] m (1 nm to the diagonal of the"
        " mesh's bounding box)"
    );
    for (const word key : {"radius", "rCut"})
    {
        // Only where given: meshPoisson reports a missing one
        if (coeffs.found(key))
        {
            getChecked<scalar>
            (
                coeffs, key,
                [diagonal](const scalar r)
                {
                    return r >= inputLimits::sizeMin && r <= diagonal;
                },
                range
            );
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
    // The local parcels: the solver exchanges its own halo (the charges
    // within reach of each processor's cells)
    const label n = this->owner().size();
    pointField x(n);
    scalarField q(n);
    List<labelPair> keys(n);
    labelList cells(n);
    label i = 0;
    for (const auto& p : this->owner())
    {
        x[i] = p.centre();
        q[i] = p.q();
        keys[i] = labelPair(p.origProc(), p.origId());
        cells[i] = p.cell();
        ++i;
    }

    // Mesh field at the parcels: interpolated (cellCentroid: their own tet
    // coordinates, no search; at the centre within the cell while lazy
    // tracking lets it drift) or averaged over their shapes (shaped, in
    // addNearField); then the near-field correction
    solver_->update(x, q, keys, cells);
    vectorField E(n, Zero);
    if (solver_->correction() == meshPoisson::correctionType::cellCentroid)
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
    solver_->addNearField(x, E);

    // The contact partners' charges for the reduced-stiffness correction
    pointField xS;
    scalarField qS;
    labelList ids;
    this->gatherPairHalo(xS, qS, ids);
    this->setFields(xS, qS, ids, E);
}


// ************************************************************************* //
