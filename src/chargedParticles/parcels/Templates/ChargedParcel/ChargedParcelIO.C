/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedParcel.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::ChargedParcel<ParcelType>::propertyList_ =
    Foam::ChargedParcel<ParcelType>::propertyList();

template<class ParcelType>
const std::size_t Foam::ChargedParcel<ParcelType>::sizeofFields
(
    offsetof(ChargedParcel<ParcelType>, fE_) + sizeof(vector)
  - offsetof(ChargedParcel<ParcelType>, q_)
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::ChargedParcel<ParcelType>::ChargedParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    q_(0),
    fE_(Zero)
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is >> q_ >> fE_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            // Non-native label or scalar size
            is.beginRawRead();
            readRawScalar(is, &q_);
            readRawScalar(is, fE_.data(), vector::nComponents);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&q_), sizeofFields);
        }
    }

    is.check(FUNCTION_NAME);
}


template<class ParcelType>
template<class CloudType>
void Foam::ChargedParcel<ParcelType>::readFields(CloudType& c)
{
    const bool valid = c.size();

    ParcelType::readFields(c);

    IOField<scalar> q(c.fieldIOobject("q", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, q);

    IOField<vector> fE(c.fieldIOobject("fE", IOobject::MUST_READ), valid);
    c.checkFieldIOobject(c, fE);

    label i = 0;
    for (ChargedParcel<ParcelType>& p : c)
    {
        p.q_ = q[i];
        p.fE_ = fE[i];
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::ChargedParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();
    const bool valid = np;

    IOField<scalar> q(c.fieldIOobject("q", IOobject::NO_READ), np);
    IOField<vector> fE(c.fieldIOobject("fE", IOobject::NO_READ), np);

    label i = 0;
    for (const ChargedParcel<ParcelType>& p : c)
    {
        q[i] = p.q();
        fE[i] = p.fE();
        ++i;
    }

    q.write(valid);
    fE.write(valid);
}


template<class ParcelType>
void Foam::ChargedParcel<ParcelType>::writeProperties
(
    Ostream& os,
    const wordRes& filters,
    const word& delim,
    const bool namesOnly
) const
{
    ParcelType::writeProperties(os, filters, delim, namesOnly);

    #undef  writeProp
    #define writeProp(Name, Value)                                            \
        ParcelType::writeProperty(os, Name, Value, namesOnly, delim, filters)

    writeProp("q", q_);
    writeProp("fE", fE_);

    #undef writeProp
}


template<class ParcelType>
template<class CloudType>
void Foam::ChargedParcel<ParcelType>::readObjects
(
    CloudType& c,
    const objectRegistry& obr
)
{
    ParcelType::readObjects(c, obr);

    if (!c.size()) return;

    const auto& q = cloud::lookupIOField<scalar>("q", obr);
    const auto& fE = cloud::lookupIOField<vector>("fE", obr);

    label i = 0;
    for (ChargedParcel<ParcelType>& p : c)
    {
        p.q_ = q[i];
        p.fE_ = fE[i];
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::ChargedParcel<ParcelType>::writeObjects
(
    const CloudType& c,
    objectRegistry& obr
)
{
    ParcelType::writeObjects(c, obr);

    const label np = c.size();

    auto& q = cloud::createIOField<scalar>("q", np, obr);
    auto& fE = cloud::createIOField<vector>("fE", np, obr);

    label i = 0;
    for (const ChargedParcel<ParcelType>& p : c)
    {
        q[i] = p.q();
        fE[i] = p.fE();
        ++i;
    }
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const ChargedParcel<ParcelType>& p
)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const ParcelType&>(p)
            << token::SPACE << p.q()
            << token::SPACE << p.fE();
    }
    else
    {
        os  << static_cast<const ParcelType&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.q_),
            ChargedParcel<ParcelType>::sizeofFields
        );
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
