/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "Pstream.H"
#include "UIndirectList.H"

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
