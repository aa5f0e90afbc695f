/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "Pstream.H"
#include "UIndirectList.H"

// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

template<class Type>
void Foam::processorHalo::exchangeWithNeighbours
(
    const labelUList& neighbours,
    const UList<List<Type>>& sendData,
    List<List<Type>>& recvData
)
{
    const label nProcs = Pstream::nProcs();
    recvData.setSize(nProcs);
    if (!Pstream::parRun())
    {
        return;
    }
    List<labelList> sendCounts(nProcs), recvCounts;
    labelList countSizes(nProcs, 0);
    List<List<Type>> toSend(nProcs);
    for (const label proci : neighbours)
    {
        sendCounts[proci] = labelList(1, sendData[proci].size());
        countSizes[proci] = 1;
        toSend[proci] = sendData[proci];
    }
    Pstream::exchange<labelList, label>(sendCounts, countSizes, recvCounts);
    labelList recvSizes(nProcs, 0);
    for (const label proci : neighbours)
    {
        recvSizes[proci] = recvCounts[proci][0];
    }
    Pstream::exchange<List<Type>, Type>(toSend, recvSizes, recvData);
}


// * * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

template<class Type>
void Foam::processorHalo::gather(List<Type>& values) const
{
    values.setSize(size());
    updateHalo(values);
}


template<class Type>
void Foam::processorHalo::updateHalo(UList<Type>& values) const
{
    exchangeHalo(values);
    // The cyclic copies from their originals (local or halo)
    const label nReal = points_.size() - copyOf_.size();
    forAll(copyOf_, c)
    {
        values[nReal + c] = values[copyOf_[c]];
    }
}


template<class Type>
void Foam::processorHalo::exchangeHalo(UList<Type>& values) const
{
    if (!Pstream::parRun())
    {
        return;
    }
    // The sizes are known on both sides (no all-to-all)
    const label nProcs = Pstream::nProcs();
    List<List<Type>> sendData(nProcs), recvData;
    labelList recvSizes(nProcs, 0);
    forAll(send_, proci)
    {
        sendData[proci] = UIndirectList<Type>(values, send_[proci]);
        recvSizes[proci] = recvStart_[proci + 1] - recvStart_[proci];
    }
    Pstream::exchange<List<Type>, Type>(sendData, recvSizes, recvData);
    forAll(recvData, proci)
    {
        if (recvSizes[proci])
        {
            SubList<Type>(values, recvSizes[proci], recvStart_[proci]) =
                recvData[proci];
        }
    }
}


template<class Type>
void Foam::processorHalo::sumToOwners(UList<Type>& values) const
{
    // The cyclic copies' entries to their originals first (a halo
    // original passes them on to its owner)
    const label nReal = points_.size() - copyOf_.size();
    forAll(copyOf_, c)
    {
        values[copyOf_[c]] += values[nReal + c];
    }
    if (!Pstream::parRun())
    {
        return;
    }
    const label nProcs = Pstream::nProcs();
    List<List<Type>> sendData(nProcs), recvData;
    labelList recvSizes(nProcs, 0);
    forAll(send_, proci)
    {
        const label n = recvStart_[proci + 1] - recvStart_[proci];
        sendData[proci] = SubList<Type>(values, n, recvStart_[proci]);
        recvSizes[proci] = send_[proci].size();
    }
    Pstream::exchange<List<Type>, Type>(sendData, recvSizes, recvData);
    forAll(recvData, proci)
    {
        if (recvSizes[proci])
        {
            forAll(send_[proci], k)
            {
                values[send_[proci][k]] += recvData[proci][k];
            }
        }
    }
}


// ************************************************************************* //
