/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "EllipsoidParcel.H"
#include "IOstreams.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::EllipsoidParcel<ParcelType>::propertyList_ =
    Foam::EllipsoidParcel<ParcelType>::propertyList();

template<class ParcelType>
const std::size_t Foam::EllipsoidParcel<ParcelType>::sizeofFields
(
    offsetof(EllipsoidParcel<ParcelType>, orientation_) + sizeof(quaternion)
  - offsetof(EllipsoidParcel<ParcelType>, semiAxes_)
);


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

template<class ParcelType>
Foam::EllipsoidParcel<ParcelType>::EllipsoidParcel
(
    const polyMesh& mesh,
    Istream& is,
    bool readFields,
    bool newFormat
)
:
    ParcelType(mesh, is, readFields, newFormat),
    semiAxes_(Zero),
    orientation_(quaternion::I),
    received_(false)
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is >> semiAxes_ >> orientation_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            // Non-native label or scalar size
            is.beginRawRead();
            readRawScalar(is, semiAxes_.data(), vector::nComponents);
            scalar w = 0;
            vector v(Zero);
            readRawScalar(is, &w);
            readRawScalar(is, v.data(), vector::nComponents);
            orientation_ = quaternion(w, v);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&semiAxes_), sizeofFields);
        }
    }

    is.check(FUNCTION_NAME);
}


template<class ParcelType>
template<class CloudType>
void Foam::EllipsoidParcel<ParcelType>::readFields(CloudType& c)
{
    const bool valid = c.size();

    ParcelType::readFields(c);

    IOField<vector> semiAxes
    (
        c.fieldIOobject("semiAxes", IOobject::MUST_READ),
        valid
    );
    c.checkFieldIOobject(c, semiAxes);

    IOField<vector> eps
    (
        c.fieldIOobject("orientationEps", IOobject::MUST_READ),
        valid
    );
    c.checkFieldIOobject(c, eps);

    IOField<scalar> eta
    (
        c.fieldIOobject("orientationEta", IOobject::MUST_READ),
        valid
    );
    c.checkFieldIOobject(c, eta);

    label i = 0;
    for (EllipsoidParcel<ParcelType>& p : c)
    {
        p.semiAxes_ = semiAxes[i];
        p.orientation_ = quaternion(eta[i], eps[i]);
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::EllipsoidParcel<ParcelType>::writeFields(const CloudType& c)
{
    ParcelType::writeFields(c);

    const label np = c.size();
    const bool valid = np;

    IOField<vector> semiAxes(c.fieldIOobject("semiAxes", IOobject::NO_READ), np);
    IOField<vector> eps(c.fieldIOobject("orientationEps", IOobject::NO_READ), np);
    IOField<scalar> eta(c.fieldIOobject("orientationEta", IOobject::NO_READ), np);
    IOField<vector> omegaBody
    (
        c.fieldIOobject("omegaBody", IOobject::NO_READ),
        np
    );
    IOField<symmTensor> shape(c.fieldIOobject("shape", IOobject::NO_READ), np);

    label i = 0;
    for (const EllipsoidParcel<ParcelType>& p : c)
    {
        semiAxes[i] = p.semiAxes_;
        eps[i] = p.orientation_.v();
        eta[i] = p.orientation_.w();
        omegaBody[i] = p.omegaBody();

        // R diag(a, b, c) R^T: the ellipsoid for ParaView's Tensor Glyph
        const tensor R(p.orientation_.R());
        const vector& s = p.semiAxes_;
        shape[i] = symm
        (
            R & tensor(s.x(), 0, 0, 0, s.y(), 0, 0, 0, s.z()) & R.T()
        );
        ++i;
    }

    semiAxes.write(valid);
    eps.write(valid);
    eta.write(valid);
    omegaBody.write(valid);
    shape.write(valid);
}


template<class ParcelType>
void Foam::EllipsoidParcel<ParcelType>::writeProperties
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

    writeProp("semiAxes", semiAxes_);
    writeProp("orientationEps", orientation_.v());
    writeProp("orientationEta", orientation_.w());

    #undef writeProp
}


template<class ParcelType>
template<class CloudType>
void Foam::EllipsoidParcel<ParcelType>::readObjects
(
    CloudType& c,
    const objectRegistry& obr
)
{
    ParcelType::readObjects(c, obr);

    if (!c.size()) return;

    const auto& semiAxes = cloud::lookupIOField<vector>("semiAxes", obr);
    const auto& eps = cloud::lookupIOField<vector>("orientationEps", obr);
    const auto& eta = cloud::lookupIOField<scalar>("orientationEta", obr);

    label i = 0;
    for (EllipsoidParcel<ParcelType>& p : c)
    {
        p.semiAxes_ = semiAxes[i];
        p.orientation_ = quaternion(eta[i], eps[i]);
        ++i;
    }
}


template<class ParcelType>
template<class CloudType>
void Foam::EllipsoidParcel<ParcelType>::writeObjects
(
    const CloudType& c,
    objectRegistry& obr
)
{
    ParcelType::writeObjects(c, obr);

    const label np = c.size();

    auto& semiAxes = cloud::createIOField<vector>("semiAxes", np, obr);
    auto& eps = cloud::createIOField<vector>("orientationEps", np, obr);
    auto& eta = cloud::createIOField<scalar>("orientationEta", np, obr);

    label i = 0;
    for (const EllipsoidParcel<ParcelType>& p : c)
    {
        semiAxes[i] = p.semiAxes_;
        eps[i] = p.orientation_.v();
        eta[i] = p.orientation_.w();
        ++i;
    }
}


// * * * * * * * * * * * * * * * IOstream Operators  * * * * * * * * * * * * //

template<class ParcelType>
Foam::Ostream& Foam::operator<<
(
    Ostream& os,
    const EllipsoidParcel<ParcelType>& p
)
{
    if (os.format() == IOstream::ASCII)
    {
        os  << static_cast<const ParcelType&>(p)
            << token::SPACE << p.semiAxes_
            << token::SPACE << p.orientation_;
    }
    else
    {
        os  << static_cast<const ParcelType&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.semiAxes_),
            EllipsoidParcel<ParcelType>::sizeofFields
        );
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
