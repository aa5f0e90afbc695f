/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ImageCoulomb.H"
#include "wallPolyPatch.H"
#include "wordRes.H"
#include "unitConversion.H"
#include "facePlanes.H"
#include "checkedEntry.H"

// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

template<class CloudType>
Foam::labelList Foam::ImageCoulomb<CloudType>::groundedPatches
(
    const dictionary& coeffs,
    const polyBoundaryMesh& pbm
)
{
    // The grounded patches: the listed names / regexes (each must match a
    // non-coupled patch), else every wall patch
    DynamicList<label> ids;
    if (coeffs.found("patches"))
    {
        const wordRes select(coeffs.get<wordRes>("patches"));
        if (select.empty())
        {
            FatalIOErrorInFunction(coeffs)
                << "Entry patches in " << coeffs.name().c_str()
                << " is empty: list the grounded planar wall patches (or"
                << " leave it out for all wall patches)"
                << exit(FatalIOError);
        }
        for (const wordRe& w : select)
        {
            bool matched = false;
            forAll(pbm, patchi)
            {
                const polyPatch& pp = pbm[patchi];
                if (!pp.coupled() && w.match(pp.name()))
                {
                    matched = true;
                    if (!ids.found(patchi))
                    {
                        ids.append(patchi);
                    }
                }
            }
            if (!matched)
            {
                wordList names;
                forAll(pbm, patchi)
                {
                    if (!pbm[patchi].coupled())
                    {
                        names.append(pbm[patchi].name());
                    }
                }
                FatalIOErrorInFunction(coeffs)
                    << "Entry patches in " << coeffs.name().c_str()
                    << ": " << w << " matches no (non-coupled) patch."
                    << " The patches are " << names << exit(FatalIOError);
            }
        }
    }
    else
    {
        forAll(pbm, patchi)
        {
            if (isA<wallPolyPatch>(pbm[patchi]))
            {
                ids.append(patchi);
            }
        }
        if (ids.empty())
        {
            FatalIOErrorInFunction(coeffs)
                << "No wall patch in the mesh for the image charges of "
                << coeffs.name().c_str()
                << ": list the grounded planar patches in entry patches"
                << exit(FatalIOError);
        }
    }
    return labelList(ids);
}


template<class CloudType>
Foam::groundedPlanes Foam::ImageCoulomb<CloudType>::wallPlanes
(
    const dictionary& coeffs,
    const polyMesh& mesh
)
{
    const polyBoundaryMesh& pbm = mesh.boundaryMesh();

    const scalar featureAngle = getCheckedOrDefault<scalar>
    (
        coeffs, "featureAngle", 30,
        [](const scalar a) { return a > 0 && a < 90; },
        " (0, 90)", " [deg]"
    );
    const scalar tol = getCheckedOrDefault<scalar>
    (
        coeffs, "planeTolerance", 1e-6,
        [](const scalar t) { return t > 0 && t < 1e-2; },
        " (0, 1e-2)"
    );

    const labelList ids(groundedPatches(coeffs, pbm));

    // Split each patch into planes: faces grouped by unit normal and
    // offset n.x. Neighbouring faces of different planes at less than
    // featureAngle mean a curved wall (images need planes)
    const scalar distTol = tol*mag(mesh.bounds().span());
    const scalar cosFeature = Foam::cos(degToRad(featureAngle));
    facePlanes planes(tol, distTol);

    for (const label patchi : ids)
    {
        const polyPatch& pp = pbm[patchi];
        const vectorField nf(pp.faceAreas()/mag(pp.faceAreas()));
        const vectorField::subField xf(pp.faceCentres());
        const label start = planes.size();
        labelList plane(pp.size(), -1);
        forAll(pp, facei)
        {
            plane[facei] = planes.insert(nf[facei], xf[facei], start);
        }

        scalar kink = -1;       // cosine of the smallest kink found
        const labelListList& edgeFaces = pp.edgeFaces();
        for (label edgei = 0; edgei < pp.nInternalEdges(); ++edgei)
        {
            const label f0 = edgeFaces[edgei][0];
            const label f1 = edgeFaces[edgei][1];
            if (plane[f0] != plane[f1])
            {
                kink = max(kink, nf[f0] & nf[f1]);
            }
        }
        reduce(kink, maxOp<scalar>());
        if (kink > cosFeature)
        {
            FatalIOErrorInFunction(coeffs)
                << "Entry patches in " << coeffs.name().c_str()
                << ": patch " << pp.name() << " is not planar: neighbouring"
                << " faces meet at " << radToDeg(Foam::acos(min(kink, 1.0)))
                << " deg < featureAngle " << featureAngle
                << " deg (a curved wall). The image charges need planar"
                << " walls (pieces meeting at sharp edges)"
                << exit(FatalIOError);
        }
    }

    // The planes of all processors, merged in processor order: the same
    // list everywhere (and the same as in serial up to round-off)
    planes.mergeProcessors();
    if (!planes.size())
    {
        FatalIOErrorInFunction(coeffs)
            << "The grounded patches of " << coeffs.name().c_str()
            << " have no faces" << exit(FatalIOError);
    }

    return groundedPlanes(planes.points(), planes.normals(), tol);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class CloudType>
Foam::ImageCoulomb<CloudType>::ImageCoulomb
(
    const dictionary& dict,
    CloudType& owner
)
:
    CoulombElectrostatics<CloudType>(dict, owner, typeName, true),
    planes_(wallPlanes(this->coeffDict(), owner.mesh()))
{
    Info<< "    Pairwise Coulomb sum and grounded-wall image charges within"
        << " rCut = " << this->rCut_ << " m (cell list), medium epsilonR = "
        << this->coulomb_.epsilonR() << nl
        << "    " << planes_.size() << " wall planes (infinite; normal,"
        << " point):" << nl;
    forAll(planes_.normals(), i)
    {
        Info<< "        " << planes_.normals()[i] << "  "
            << planes_.points()[i] << nl;
    }
    Info<< endl;

    if (!planes_.rightAngled())
    {
        WarningInFunction
            << "The wall planes of " << this->coeffDict().name().c_str()
            << " are not all perpendicular or parallel: no composed images"
            << " across the others, the image field is approximate there"
            << endl;
    }
}


template<class CloudType>
Foam::ImageCoulomb<CloudType>::ImageCoulomb
(
    const ImageCoulomb<CloudType>& em
)
:
    CoulombElectrostatics<CloudType>(em),
    planes_(em.planes_)
{}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class CloudType>
void Foam::ImageCoulomb<CloudType>::calculate()
{
    // The local parcels and the halo of the other processors' parcels
    // within the cutoff: an image is at least as far from every point of
    // the domain as the charge it mirrors, so the halo's images are all
    // the images within the cutoff; real charges and images both
    // truncated at rCut (Rasera 2022 section 2.4)
    pointField xS;
    scalarField qS;
    labelList ids;
    this->gatherPairHalo(xS, qS, ids);

    const label n = this->owner().size();
    const pointField x(SubList<point>(xS, n));
    vectorField E(n, Zero);
    planes_.addFieldsWithinCutoff
    (
        this->coulomb_, x, xS, qS, this->rCut_, E, 0
    );

    this->setFields(xS, qS, ids, E);
}


// ************************************************************************* //
