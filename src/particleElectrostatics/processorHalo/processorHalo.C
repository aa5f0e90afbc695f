/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "polyMesh.H"
#include "Pstream.H"
#include "UIndirectList.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::List<Foam::boundBox> Foam::processorHalo::processorBoxes
(
    const polyMesh& mesh
)
{
    List<boundBox> boxes(Pstream::nProcs());
    boxes[Pstream::myProcNo()] = boundBox(mesh.points(), false);
    Pstream::gatherList(boxes);
    Pstream::scatterList(boxes);
    return boxes;
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

    // The counts first, between neighbours only (both sides know who
    // they are: no all-to-all of sizes), then the points
    const label nProcs = Pstream::nProcs();
    List<labelList> sendCounts(nProcs), recvCounts;
    labelList recvCountSizes(nProcs, 0);
    List<pointField> sendPoints(nProcs), recvPoints;
    forAll(boxes, proci)
    {
        if (sends(proci, me))
        {
            recvCountSizes[proci] = 1;
        }
        if (!sends(me, proci))
        {
            continue;
        }
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
        sendCounts[proci] = labelList(1, send_[proci].size());
        sendPoints[proci] = pointField(UIndirectList<point>(x, send_[proci]));
    }
    Pstream::exchange<labelList, label>(sendCounts, recvCountSizes, recvCounts);

    labelList recvSizes(nProcs, 0);
    forAll(recvCounts, proci)
    {
        if (recvCountSizes[proci])
        {
            recvSizes[proci] = recvCounts[proci][0];
        }
    }
    Pstream::exchange<pointField, point>(sendPoints, recvSizes, recvPoints);

    DynamicList<point> all(points_);
    forAll(boxes, proci)
    {
        recvStart_[proci] = all.size();
        if (recvSizes[proci])
        {
            all.append(recvPoints[proci]);
        }
    }
    recvStart_[nProcs] = all.size();
    points_.transfer(all);
}


// ************************************************************************* //
