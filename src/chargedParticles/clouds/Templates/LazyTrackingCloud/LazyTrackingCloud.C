/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "LazyTrackingCloud.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::scalar Foam::LazyTrackingCloud<CloudType>::readTrackingTolerance() const
{
    const dictionary& solDict = this->solution().dict();
    const scalar tol = getCheckedOrDefault<scalar>
    (
        solDict, "trackingTolerance", 1e-3,
        [](const scalar t) { return t >= 0 && t <= 0.5; },
        " [0, 0.5] (fraction of a cell; 0: track every step)"
    );

    // The deviation from the mesh centre of 1-D/2-D cases is applied by
    // the tracking
    return this->mesh().nSolutionD() == 3 ? tol : 0;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::LazyTrackingCloud<CloudType>::LazyTrackingCloud
(
    const word& cloudName,
    const volScalarField& rho,
    const volVectorField& U,
    const volScalarField& mu,
    const dimensionedVector& g,
    bool readFields
)
:
    CloudType(cloudName, rho, U, mu, g, readFields),
    trackingTolerance_(readTrackingTolerance())
{}


template<class CloudType>
Foam::LazyTrackingCloud<CloudType>::LazyTrackingCloud
(
    LazyTrackingCloud<CloudType>& c,
    const word& name
)
:
    CloudType(c, name),
    trackingTolerance_(c.trackingTolerance_)
{}


template<class CloudType>
Foam::LazyTrackingCloud<CloudType>::LazyTrackingCloud
(
    const fvMesh& mesh,
    const word& name,
    const LazyTrackingCloud<CloudType>& c
)
:
    CloudType(mesh, name, c),
    trackingTolerance_(c.trackingTolerance_)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::LazyTrackingCloud<CloudType>::trackEveryStep(const string& reason)
{
    if (trackingTolerance_ > 0)
    {
        Info<< "    Lazy tracking off: " << reason.c_str() << endl;
        trackingTolerance_ = 0;
    }
}


template<class CloudType>
void Foam::LazyTrackingCloud<CloudType>::trackDrifts()
{
    for (parcelType& p : *this)
    {
        p.trackDrift();
    }
}


// ************************************************************************* //
