/*---------------------------------------------------------------------------*\
    chargedFoam: charged dielectric particles for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "particleMaterials.H"
#include "boolList.H"

// * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * * //

const Foam::word Foam::particleMaterials::defaultName("default");


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::particleMaterials::particleMaterials(const dictionary& constProps)
:
    names_(),
    dicts_()
{
    // The defaults: every top-level entry but the material list
    dictionary defaults(constProps);
    defaults.remove("materials");

    if (!constProps.found("materials"))
    {
        names_ = wordList(1, defaultName);
        dicts_.setSize(1);
        dicts_.set(0, new dictionary(defaults));
        return;
    }

    if (!constProps.isDict("materials"))
    {
        FatalIOErrorInFunction(constProps)
            << "Entry materials in " << constProps.name().c_str()
            << " must be a dictionary of materials,"
            << " e.g. materials { PTFE {} nylon { rho0 1140; } }"
            << exit(FatalIOError);
    }
    const dictionary& materials = constProps.subDict("materials");
    const wordList names(materials.toc());
    if (names.empty())
    {
        FatalIOErrorInFunction(materials)
            << "Entry materials in " << constProps.name().c_str()
            << " lists no material: give at least one, or leave the entry"
            << " out (one material from the entries of constantProperties)"
            << exit(FatalIOError);
    }

    names_ = names;
    dicts_.setSize(names.size());
    forAll(names, m)
    {
        if (!materials.isDict(names[m]))
        {
            FatalIOErrorInFunction(materials)
                << "Entry materials/" << names[m] << " in "
                << constProps.name().c_str() << " must be a dictionary of"
                << " the material's properties (rho0, youngsModulus,"
                << " poissonsRatio; {} for the defaults)"
                << exit(FatalIOError);
        }
        const dictionary& own = materials.subDict(names[m]);
        dictionary* d = new dictionary(defaults);
        d->merge(own);
        d->name() = own.name();
        dicts_.set(m, d);
    }
}


Foam::particleMaterials::particleMaterials(const particleMaterials& m)
:
    names_(m.names_),
    dicts_(m.dicts_)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::label Foam::particleMaterials::find
(
    const word& name,
    const dictionary& context,
    const word& entry
) const
{
    const label m = names_.find(name);
    if (m < 0)
    {
        FatalIOErrorInFunction(context)
            << "Entry " << entry << " in " << context.name().c_str()
            << " names material " << name << ", which the cloud does not"
            << " have: its materials (constantProperties/materials) are "
            << names_ << exit(FatalIOError);
    }
    return m;
}


Foam::label Foam::particleMaterials::check
(
    const label m,
    const dictionary& context
) const
{
    if (!(m >= 0 && m < size()))
    {
        FatalIOErrorInFunction(context)
            << "A parcel has material " << m << ", out of range [0, "
            << size() - 1 << "]: the cloud's materials are " << names_
            << " (constantProperties/materials)" << exit(FatalIOError);
    }
    return m;
}


Foam::List<const Foam::dictionary*> Foam::particleMaterials::pairEntries
(
    const dictionary& coeffs,
    boolList& swapped
) const
{
    const label n = size();
    List<const dictionary*> entries(n*n, nullptr);
    swapped = boolList(n*n, false);
    if (!coeffs.found("materialPairs"))
    {
        return entries;
    }
    const dictionary& pairs = coeffs.subDict("materialPairs");

    for (const entry& e : pairs)
    {
        if (!e.isDict() || !e.dict().found("materials"))
        {
            FatalIOErrorInFunction(pairs)
                << "Entry " << e.keyword() << " in " << pairs.name().c_str()
                << " must be a dictionary naming its two materials,"
                << " e.g. { materials (" << names_.first() << " "
                << names_.last() << "); ... }" << exit(FatalIOError);
        }
        const dictionary& d = e.dict();
        const wordList pair(d.get<wordList>("materials"));
        if (pair.size() != 2)
        {
            FatalIOErrorInFunction(d)
                << "Entry materials in " << d.name().c_str() << " names "
                << pair.size() << " materials: it must name two, e.g. ("
                << names_.first() << " " << names_.last() << ")"
                << exit(FatalIOError);
        }
        const label a = find(pair[0], d, "materials");
        const label b = find(pair[1], d, "materials");
        if (entries[pairIndex(a, b)])
        {
            FatalIOErrorInFunction(d)
                << "The material pair (" << pair[0] << " " << pair[1]
                << ") of " << d.name().c_str() << " is also given by "
                << entries[pairIndex(a, b)]->name().c_str()
                << ": list each pair once" << exit(FatalIOError);
        }
        entries[pairIndex(a, b)] = &d;
        entries[pairIndex(b, a)] = &d;
        swapped[pairIndex(b, a)] = (a != b);
    }
    return entries;
}


// ************************************************************************* //
