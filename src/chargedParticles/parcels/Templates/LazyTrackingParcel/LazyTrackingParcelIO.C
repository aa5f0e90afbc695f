/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "LazyTrackingParcel.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::LazyTrackingParcel<ParcelType>::propertyList_ =
    Foam::LazyTrackingParcel<ParcelType>::propertyList();

template<class ParcelType>
const std::size_t Foam::LazyTrackingParcel<ParcelType>::sizeofFields
(
    sizeof(vector)
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::LazyTrackingParcel<ParcelType>::LazyTrackingParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    drift_(Zero),
    allowedDrift_(-1),
    centre_(Zero),
    centreValid_(false)
{
    // The drift is streamed for the copies referred to other processors
    // (a transferred parcel has none: it was tracked); written fields
    // have none (tracked before writing)
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is >> drift_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            // Non-native label or scalar size
            is.beginRawRead();
            readRawScalar(is, drift_.data(), vector::nComponents);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&drift_), sizeofFields);
        }
    }

    is.check(FUNCTION_NAME);
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const LazyTrackingParcel<ParcelType>& p
)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const ParcelType&>(p)
            << token::SPACE << p.drift_;
    }
    else
    {
        os  << static_cast<const ParcelType&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.drift_),
            LazyTrackingParcel<ParcelType>::sizeofFields
        );
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
