/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "processorHalo.H"
#include "Pstream.H"
#include "PstreamBuffers.H"
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
    if (size() == nLocal_ && !Pstream::parRun())
    {
        return;
    }
    const label me = Pstream::myProcNo();
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(send_, proci)
    {
        if (send_[proci].size())
        {
            UOPstream toProc(proci, pBufs);
            toProc << List<Type>(UIndirectList<Type>(values, send_[proci]));
        }
    }
    pBufs.finishedSends();
    forAll(send_, proci)
    {
        const label start = recvStart_[proci];
        const label n = recvStart_[proci + 1] - start;
        if (proci != me && n)
        {
            UIPstream fromProc(proci, pBufs);
            const List<Type> received(fromProc);
            SubList<Type>(values, n, start) = received;
        }
    }
}


template<class Type>
void Foam::processorHalo::sumToOwners(UList<Type>& values) const
{
    if (size() == nLocal_ && !Pstream::parRun())
    {
        return;
    }
    const label me = Pstream::myProcNo();
    PstreamBuffers pBufs(Pstream::commsTypes::nonBlocking);
    forAll(send_, proci)
    {
        const label start = recvStart_[proci];
        const label n = recvStart_[proci + 1] - start;
        if (proci != me && n)
        {
            UOPstream toProc(proci, pBufs);
            toProc << List<Type>(SubList<Type>(values, n, start));
        }
    }
    pBufs.finishedSends();
    forAll(send_, proci)
    {
        if (send_[proci].size())
        {
            UIPstream fromProc(proci, pBufs);
            const List<Type> received(fromProc);
            forAll(received, k)
            {
                values[send_[proci][k]] += received[k];
            }
        }
    }
}


// ************************************************************************* //
