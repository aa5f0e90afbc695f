/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "polyMesh.H"
#include "Pstream.H"
#include "UIndirectList.H"
#include "MeshObject.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

namespace Foam
{

//- The processors' boxes, kept with the mesh (one exchange per mesh; a
//  GeometricMeshObject is destroyed when the points move)
class processorMeshBoxes
:
    public MeshObject<polyMesh, GeometricMeshObject, processorMeshBoxes>
{
    List<boundBox> boxes_;

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
    }

    const List<boundBox>& boxes() const
    {
        return boxes_;
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
    const UList<vector>& translations
)
:
    nLocal_(x.size()),
    send_(Pstream::nProcs()),
    recvStart_(Pstream::nProcs() + 1, x.size()),
    points_(x)
{
    if (!Pstream::parRun() || !(range > 0))
    {
        return;
    }

    const label me = Pstream::myProcNo();
    const vector margin(range, range, range);
    const auto grown = [&](const label j)
    {
        return boundBox(boxes[j].min() - margin, boxes[j].max() + margin);
    };
    // The shifts of a point that may lie within reach: itself and its
    // cyclic copies
    List<vector> shifts(translations.size() + 1, Zero);
    forAll(translations, k)
    {
        shifts[k + 1] = translations[k];
    }
    // i sends to j: some shift of i's box overlaps j's grown box (the
    // same test on both sides)
    const auto sends = [&](const label i, const label j)
    {
        if (i == j || !boxes[i].valid() || !boxes[j].valid())
        {
            return false;
        }
        const boundBox g(grown(j));
        for (const vector& t : shifts)
        {
            if (g.overlaps(boundBox(boxes[i].min() + t, boxes[i].max() + t)))
            {
                return true;
            }
        }
        return false;
    };

    // The points, with their counts between the neighbours only (both
    // sides know who they are: sends() is symmetric, the shifts coming
    // in pairs)
    DynamicList<label> neighbours;
    List<List<point>> sendPoints(Pstream::nProcs()), recvPoints;
    forAll(boxes, proci)
    {
        if (!sends(me, proci))
        {
            continue;
        }
        neighbours.append(proci);
        const boundBox g(grown(proci));
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
