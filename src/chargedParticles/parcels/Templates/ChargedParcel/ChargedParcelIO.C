/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ChargedParcel.H"
#include "IOstreams.H"
#include "labelFieldIOField.H"
#include "scalarFieldIOField.H"
#include "vectorFieldIOField.H"

// * * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * //

template<class ParcelType>
Foam::string Foam::ChargedParcel<ParcelType>::propertyList_ =
    Foam::ChargedParcel<ParcelType>::propertyList();

template<class ParcelType>
const std::size_t Foam::ChargedParcel<ParcelType>::sizeofFields
(
    offsetof(ChargedParcel<ParcelType>, dipole_) + sizeof(vector)
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
    epsilonR_(1),
    fE_(Zero),
    tE_(Zero),
    E_(Zero),
    dipole_(Zero),
    material_(0),
    chargingRecords_()
{
    if (readFields)
    {
        if (is.format() == IOstream::ASCII)
        {
            is >> q_ >> epsilonR_ >> fE_ >> tE_ >> E_ >> dipole_;
        }
        else if (!is.checkLabelSize<>() || !is.checkScalarSize<>())
        {
            // Non-native label or scalar size
            is.beginRawRead();
            readRawScalar(is, &q_);
            readRawScalar(is, &epsilonR_);
            readRawScalar(is, fE_.data(), vector::nComponents);
            readRawScalar(is, tE_.data(), vector::nComponents);
            readRawScalar(is, E_.data(), vector::nComponents);
            readRawScalar(is, dipole_.data(), vector::nComponents);
            is.endRawRead();
        }
        else
        {
            is.read(reinterpret_cast<char*>(&q_), sizeofFields);
        }

        is >> material_ >> chargingRecords_;
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

    // Optional (cases written before they existed): E is recomputed by
    // the electrostatics before it is used; no charging history means
    // every current contact counts from zero area; epsilonR defaults to
    // the constant properties', tE and the dipole to zero
    IOField<vector> E(c.fieldIOobject("E", IOobject::READ_IF_PRESENT));
    const bool haveE = E.size() == c.size();
    IOField<scalar> epsilonR
    (
        c.fieldIOobject("epsilonR", IOobject::READ_IF_PRESENT)
    );
    const bool haveEpsilonR = epsilonR.size() == c.size();
    IOField<vector> tE(c.fieldIOobject("tE", IOobject::READ_IF_PRESENT));
    const bool haveTE = tE.size() == c.size();
    IOField<vector> dipole
    (
        c.fieldIOobject("dipole", IOobject::READ_IF_PRESENT)
    );
    const bool haveDipole = dipole.size() == c.size();
    IOField<label> material
    (
        c.fieldIOobject("material", IOobject::READ_IF_PRESENT)
    );
    const bool haveMaterial = material.size() == c.size();

    const word rec("chargingRecords");
    labelFieldCompactIOField pairAccessed
    (
        c.fieldIOobject(rec + "PairAccessed", IOobject::READ_IF_PRESENT)
    );
    labelFieldCompactIOField pairOrigProc
    (
        c.fieldIOobject(rec + "PairOrigProcOfOther", IOobject::READ_IF_PRESENT)
    );
    labelFieldCompactIOField pairOrigId
    (
        c.fieldIOobject(rec + "PairOrigIdOfOther", IOobject::READ_IF_PRESENT)
    );
    scalarFieldCompactIOField pairData
    (
        c.fieldIOobject(rec + "PairData", IOobject::READ_IF_PRESENT)
    );
    labelFieldCompactIOField wallAccessed
    (
        c.fieldIOobject(rec + "WallAccessed", IOobject::READ_IF_PRESENT)
    );
    vectorFieldCompactIOField wallPRel
    (
        c.fieldIOobject(rec + "WallPRel", IOobject::READ_IF_PRESENT)
    );
    scalarFieldCompactIOField wallData
    (
        c.fieldIOobject(rec + "WallData", IOobject::READ_IF_PRESENT)
    );
    const bool haveRecords =
        pairAccessed.size() == c.size()
     && pairOrigProc.size() == c.size()
     && pairOrigId.size() == c.size()
     && pairData.size() == c.size()
     && wallAccessed.size() == c.size()
     && wallPRel.size() == c.size()
     && wallData.size() == c.size();

    label i = 0;
    for (ChargedParcel<ParcelType>& p : c)
    {
        p.q_ = q[i];
        p.epsilonR_ = haveEpsilonR ? epsilonR[i] : c.constProps().epsilonR0();
        p.fE_ = fE[i];
        if (haveE)
        {
            p.E_ = E[i];
        }
        if (haveTE)
        {
            p.tE_ = tE[i];
        }
        if (haveDipole)
        {
            p.dipole_ = dipole[i];
        }
        if (haveMaterial)
        {
            p.material_ = material[i];
        }
        if (haveRecords)
        {
            p.chargingRecords_ = chargingRecordList
            (
                pairAccessed[i],
                pairOrigProc[i],
                pairOrigId[i],
                pairData[i],
                wallAccessed[i],
                wallPRel[i],
                wallData[i]
            );
        }
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
    IOField<scalar> epsilonR
    (
        c.fieldIOobject("epsilonR", IOobject::NO_READ), np
    );
    IOField<vector> fE(c.fieldIOobject("fE", IOobject::NO_READ), np);
    IOField<vector> tE(c.fieldIOobject("tE", IOobject::NO_READ), np);
    IOField<vector> E(c.fieldIOobject("E", IOobject::NO_READ), np);
    IOField<vector> dipole(c.fieldIOobject("dipole", IOobject::NO_READ), np);
    IOField<label> material
    (
        c.fieldIOobject("material", IOobject::NO_READ), np
    );

    const word rec("chargingRecords");
    labelFieldCompactIOField pairAccessed
    (
        c.fieldIOobject(rec + "PairAccessed", IOobject::NO_READ), np
    );
    labelFieldCompactIOField pairOrigProc
    (
        c.fieldIOobject(rec + "PairOrigProcOfOther", IOobject::NO_READ), np
    );
    labelFieldCompactIOField pairOrigId
    (
        c.fieldIOobject(rec + "PairOrigIdOfOther", IOobject::NO_READ), np
    );
    scalarFieldCompactIOField pairData
    (
        c.fieldIOobject(rec + "PairData", IOobject::NO_READ), np
    );
    labelFieldCompactIOField wallAccessed
    (
        c.fieldIOobject(rec + "WallAccessed", IOobject::NO_READ), np
    );
    vectorFieldCompactIOField wallPRel
    (
        c.fieldIOobject(rec + "WallPRel", IOobject::NO_READ), np
    );
    scalarFieldCompactIOField wallData
    (
        c.fieldIOobject(rec + "WallData", IOobject::NO_READ), np
    );

    label i = 0;
    for (const ChargedParcel<ParcelType>& p : c)
    {
        q[i] = p.q();
        epsilonR[i] = p.epsilonR();
        fE[i] = p.fE();
        tE[i] = p.tE();
        E[i] = p.E();
        dipole[i] = p.dipole();
        material[i] = p.material();
        const chargingRecordList& r = p.chargingRecords();
        pairAccessed[i] = r.pairAccessed();
        pairOrigProc[i] = r.pairOrigProcOfOther();
        pairOrigId[i] = r.pairOrigIdOfOther();
        pairData[i] = r.pairData();
        wallAccessed[i] = r.wallAccessed();
        wallPRel[i] = r.wallPRel();
        wallData[i] = r.wallData();
        ++i;
    }

    q.write(valid);
    epsilonR.write(valid);
    fE.write(valid);
    tE.write(valid);
    E.write(valid);
    dipole.write(valid);
    material.write(valid);
    pairAccessed.write(valid);
    pairOrigProc.write(valid);
    pairOrigId.write(valid);
    pairData.write(valid);
    wallAccessed.write(valid);
    wallPRel.write(valid);
    wallData.write(valid);
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
    writeProp("epsilonR", epsilonR_);
    writeProp("fE", fE_);
    writeProp("tE", tE_);
    writeProp("E", E_);
    writeProp("dipole", dipole_);
    writeProp("material", material_);

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
    const auto& epsilonR = cloud::lookupIOField<scalar>("epsilonR", obr);
    const auto& fE = cloud::lookupIOField<vector>("fE", obr);
    const auto& tE = cloud::lookupIOField<vector>("tE", obr);
    const auto& E = cloud::lookupIOField<vector>("E", obr);
    const auto& dipole = cloud::lookupIOField<vector>("dipole", obr);
    const auto& material = cloud::lookupIOField<label>("material", obr);

    label i = 0;
    for (ChargedParcel<ParcelType>& p : c)
    {
        p.q_ = q[i];
        p.epsilonR_ = epsilonR[i];
        p.fE_ = fE[i];
        p.tE_ = tE[i];
        p.E_ = E[i];
        p.dipole_ = dipole[i];
        p.material_ = material[i];
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
    auto& epsilonR = cloud::createIOField<scalar>("epsilonR", np, obr);
    auto& fE = cloud::createIOField<vector>("fE", np, obr);
    auto& tE = cloud::createIOField<vector>("tE", np, obr);
    auto& E = cloud::createIOField<vector>("E", np, obr);
    auto& dipole = cloud::createIOField<vector>("dipole", np, obr);
    auto& material = cloud::createIOField<label>("material", np, obr);

    label i = 0;
    for (const ChargedParcel<ParcelType>& p : c)
    {
        q[i] = p.q();
        epsilonR[i] = p.epsilonR();
        fE[i] = p.fE();
        tE[i] = p.tE();
        E[i] = p.E();
        dipole[i] = p.dipole();
        material[i] = p.material();
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
            << token::SPACE << p.epsilonR()
            << token::SPACE << p.fE()
            << token::SPACE << p.tE()
            << token::SPACE << p.E()
            << token::SPACE << p.dipole()
            << token::SPACE << p.material()
            << token::SPACE << p.chargingRecords();
    }
    else
    {
        os  << static_cast<const ParcelType&>(p);
        os.write
        (
            reinterpret_cast<const char*>(&p.q_),
            ChargedParcel<ParcelType>::sizeofFields
        );
        os  << p.material() << p.chargingRecords();
    }

    os.check(FUNCTION_NAME);
    return os;
}


// ************************************************************************* //
