/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "polyMesh.H"
#include "Pstream.H"
#include "UIndirectList.H"
#include "MeshObject.H"
#include "cyclicPolyPatch.H"
#include "processorCyclicPolyPatch.H"
#include "SubField.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

namespace Foam
{

//- The processors' boxes and the cyclic patches' translations, kept with
//  the mesh (one exchange per mesh; a GeometricMeshObject is destroyed when
//  the points move)
class processorMeshBoxes
:
    public MeshObject<polyMesh, GeometricMeshObject, processorMeshBoxes>
{
    List<boundBox> boxes_;

    List<vector> cyclicShifts_;

    //- Their combinations (translationCombinations)
    List<vector> cyclicTranslations_;

    wordList rotationalCyclics_;

    //- One translation per cyclic pair (owner side). A processor may hold
    //  none of a patch's faces: the vector is the largest over processors
    void findCyclicShifts(const polyMesh& mesh)
    {
        const polyBoundaryMesh& pbm = mesh.boundaryMesh();
        forAll(pbm, patchi)
        {
            const cyclicPolyPatch* cpp = isA<cyclicPolyPatch>(pbm[patchi]);
            if (!cpp || !cpp->owner())
            {
                continue;
            }
            if (cpp->transform() == coupledPolyPatch::ROTATIONAL)
            {
                rotationalCyclics_.append(cpp->name());
                continue;
            }
            // The translation as found from the faces (blockMesh cyclics
            // leave separationVector unset)
            vector s(Zero);
            if (cpp->size() && cpp->separated() && cpp->separation().size())
            {
                s = cpp->separation()[0];
            }
            else if (cpp->size())
            {
                s = cpp->separationVector();
            }
            else
            {
                // A processor split along the periodic direction holds its
                // faces as processorCyclic patches (the cyclic itself has
                // none on any processor): the translation between a face
                // and its neighbour's
                for (const polyPatch& pp : pbm)
                {
                    const processorCyclicPolyPatch* pcp =
                        isA<processorCyclicPolyPatch>(pp);
                    if
                    (
                        pcp && pcp->size()
                     && (
                            pcp->referPatchID() == patchi
                         || pcp->referPatchID() == cpp->neighbPatchID()
                        )
                    )
                    {
                        s = pcp->neighbFaceCentres()[0] - pcp->faceCentres()[0];
                        break;
                    }
                }
            }
            reduce(s, maxMagSqrOp<vector>());
            if (magSqr(s) > 0)
            {
                cyclicShifts_.append(s);
            }
        }
    }

public:

    TypeName("processorMeshBoxes");

    explicit processorMeshBoxes(const polyMesh& mesh)
    :
        MeshObject<polyMesh, GeometricMeshObject, processorMeshBoxes>(mesh),
        boxes_(Pstream::nProcs())
    {
        boxes_[Pstream::myProcNo()] = boundBox(mesh.points(), false);
        Pstream::gatherList(boxes_);
        Pstream::scatterList(boxes_);
        findCyclicShifts(mesh);
        cyclicTranslations_ =
            processorHalo::translationCombinations(cyclicShifts_);
    }

    const List<boundBox>& boxes() const
    {
        return boxes_;
    }

    const List<vector>& cyclicShifts() const
    {
        return cyclicShifts_;
    }

    const List<vector>& cyclicTranslations() const
    {
        return cyclicTranslations_;
    }

    const wordList& rotationalCyclics() const
    {
        return rotationalCyclics_;
    }
};

defineTypeNameAndDebug(processorMeshBoxes, 0);

} // End namespace Foam


const Foam::List<Foam::boundBox>& Foam::processorHalo::processorBoxes
(
    const polyMesh& mesh
)
{
    return processorMeshBoxes::New(mesh).boxes();
}


namespace Foam
{

//- The mesh's boxes and translations, refusing rotational cyclic patches
static const processorMeshBoxes& translationalCyclics(const polyMesh& mesh)
{
    const processorMeshBoxes& m = processorMeshBoxes::New(mesh);
    if (m.rotationalCyclics().size())
    {
        FatalErrorInFunction
            << "Cyclic patches " << m.rotationalCyclics() << " are "
            << "rotational: the particle electrostatics sum across "
            << "translational cyclic patches only" << exit(FatalError);
    }
    return m;
}

} // End namespace Foam


const Foam::List<Foam::vector>& Foam::processorHalo::cyclicShifts
(
    const polyMesh& mesh
)
{
    return translationalCyclics(mesh).cyclicShifts();
}


const Foam::List<Foam::vector>& Foam::processorHalo::cyclicTranslations
(
    const polyMesh& mesh
)
{
    return translationalCyclics(mesh).cyclicTranslations();
}


Foam::scalar Foam::processorHalo::shortestCyclicPeriod(const polyMesh& mesh)
{
    scalar period = GREAT;
    for (const vector& s : cyclicShifts(mesh))
    {
        period = min(period, mag(s));
    }
    return period;
}


bool Foam::processorHalo::reaches
(
    const List<boundBox>& boxes,
    const label i,
    const label j,
    const scalar range,
    const UList<vector>& translations
)
{
    if (i == j || !boxes[i].valid() || !boxes[j].valid())
    {
        return false;
    }
    const vector margin(range, range, range);
    const boundBox g(boxes[j].min() - margin, boxes[j].max() + margin);
    if (g.overlaps(boxes[i]))
    {
        return true;
    }
    for (const vector& t : translations)
    {
        if (g.overlaps(boundBox(boxes[i].min() + t, boxes[i].max() + t)))
        {
            return true;
        }
    }
    return false;
}


Foam::List<Foam::vector> Foam::processorHalo::translationCombinations
(
    const UList<vector>& shifts
)
{
    label nComb = 1;
    forAll(shifts, d)
    {
        nComb *= 3;
    }
    DynamicList<vector> t(nComb - 1);
    for (label comb = 0; comb < nComb; ++comb)
    {
        vector shift(Zero);
        bool identityShift = true;
        label c = comb;
        forAll(shifts, d)
        {
            const label n = c % 3 - 1;
            c /= 3;
            if (n != 0)
            {
                shift += scalar(n)*shifts[d];
                identityShift = false;
            }
        }
        if (!identityShift)
        {
            t.append(shift);
        }
    }
    return List<vector>(std::move(t));
}


Foam::List<Foam::vector> Foam::processorHalo::boxTranslations
(
    const vector& L
)
{
    List<vector> t;
    for (label i = -1; i <= 1; ++i)
    {
        for (label j = -1; j <= 1; ++j)
        {
            for (label k = -1; k <= 1; ++k)
            {
                if (i || j || k)
                {
                    t.append(vector(i*L.x(), j*L.y(), k*L.z()));
                }
            }
        }
    }
    return t;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::processorHalo::processorHalo
(
    const List<boundBox>& boxes,
    const UList<point>& x,
    const scalar range,
    const UList<vector>& translations,
    const bool unfold
)
:
    nLocal_(x.size()),
    send_(Pstream::nProcs()),
    recvStart_(Pstream::nProcs() + 1, x.size()),
    points_(x)
{
    if (!(range > 0))
    {
        return;
    }

    if (Pstream::parRun())
    {
        exchangePoints(boxes, x, range, translations);
    }
    const boundBox& mine = boxes[Pstream::myProcNo()];
    if (unfold && translations.size() && mine.valid())
    {
        const vector margin(range, range, range);
        appendCopies
        (
            translations,
            boundBox(mine.min() - margin, mine.max() + margin)
        );
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::processorHalo::appendCopies
(
    const UList<vector>& translations,
    const boundBox& reach
)
{
    // In the order of the translations, then of the points (local and
    // halo)
    const label nReal = points_.size();
    DynamicList<point> all(points_);
    DynamicList<label> copyOf;
    for (const vector& t : translations)
    {
        for (label i = 0; i < nReal; ++i)
        {
            if (reach.contains(points_[i] + t))
            {
                all.append(points_[i] + t);
                copyOf.append(i);
            }
        }
    }
    copyOf_.transfer(copyOf);
    points_.transfer(all);
}


void Foam::processorHalo::updateHaloPoints(UList<point>& values) const
{
    updateHalo(values);
    const label nReal = points_.size() - copyOf_.size();
    forAll(copyOf_, c)
    {
        values[nReal + c] += points_[nReal + c] - points_[copyOf_[c]];
    }
}


void Foam::processorHalo::exchangePoints
(
    const List<boundBox>& boxes,
    const UList<point>& x,
    const scalar range,
    const UList<vector>& translations
)
{
    const label me = Pstream::myProcNo();
    const vector margin(range, range, range);
    // The shifts of a point that may lie within reach: itself and its
    // cyclic copies
    List<vector> shifts(translations.size() + 1, Zero);
    forAll(translations, k)
    {
        shifts[k + 1] = translations[k];
    }

    // The points, with their counts between the neighbours only (both
    // sides know who they are: reaches() is symmetric, the translations
    // coming in pairs)
    DynamicList<label> neighbours;
    List<List<point>> sendPoints(Pstream::nProcs()), recvPoints;
    forAll(boxes, proci)
    {
        if (!reaches(boxes, me, proci, range, translations))
        {
            continue;
        }
        neighbours.append(proci);
        const boundBox g
        (
            boxes[proci].min() - margin,
            boxes[proci].max() + margin
        );
        DynamicList<label> idx;
        forAll(x, i)
        {
            for (const vector& t : shifts)
            {
                if (g.contains(x[i] + t))
                {
                    idx.append(i);
                    break;
                }
            }
        }
        send_[proci].transfer(idx);
        sendPoints[proci] = UIndirectList<point>(x, send_[proci]);
    }
    exchangeWithNeighbours<point>(neighbours, sendPoints, recvPoints);

    DynamicList<point> all(points_);
    forAll(boxes, proci)
    {
        recvStart_[proci] = all.size();
        all.append(recvPoints[proci]);
    }
    recvStart_[Pstream::nProcs()] = all.size();
    points_.transfer(all);
}


// ************************************************************************* //
