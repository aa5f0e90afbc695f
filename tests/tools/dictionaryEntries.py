#!/usr/bin/env python3
"""
The dictionary entries chargedFoam's C++ code reads, and a check of the
reference doc/reference.md against them.

    dictionaryEntries.py [paths...]                  list the entry names
    dictionaryEntries.py --sites [paths...]          ... with file:line of each read
    dictionaryEntries.py --check doc/reference.md [paths...]

paths: C++ files or directories (default: src, applications/solvers and
applications/utilities of the project; lnInclude and Make are skipped).
applications/benchmarks is not scanned: its programs take command-line
options only and read no case dictionary.

What counts as a read (comments stripped, calls may span lines):
  1. dictionary member calls whose first argument is a string literal:
     get, getOrDefault, getCheck, getCheckOrDefault, getOrAdd,
     lookupOrDefault, lookupOrAddDefault, readIfPresent, readEntry, lookup,
     lookupEntry, lookupEntryPtr, found, subDict, optionalSubDict,
     subOrEmptyDict, isDict, findDict, findEntry, getModelProperty (a
     sub-model's restart state), Enum::lookupOrDefault / Enum::get
     ("key", dict, ...)). Calls on `args` (argList: command-line options)
     are not dictionary reads and are skipped.
  2. Calls of the project's helpers that read an entry named by a string
     literal argument (every literal of the call counts):
     readPositive, readFinite, readPoisson, readParcelScalar, readScalar,
     readLabel, oneOf, and the lambda `get(dict, "key", positive)`
     (RaseraTriboCharging); Function1<Type>::New("key", dict); and
     getChecked / getCheckedOrDefault / getPositive /
     getPositiveOrDefault(dict, "key", ...) (checkedEntry.H), whose second
     argument is the key (their other literals are range texts).
  3. A member call whose key is an identifier defined in the same file as
     a word constant with string literals (`const word key(c ? "a" : "b")`)
     reads those literals.
  4. Every other member call of (1) with a non-literal key is a warning
     unless it is listed in REVIEWED below (file, text of the key) with
     the names it reads or why it reads none. --check fails on
     unreviewed ones, and on REVIEWED items whose key text is gone.
  5. Entries read by a constructor that takes the dictionary (no lookup
     call to scan) are listed in CONSTRUCTOR_READS with a text of the
     code (an anchor) that must still be there.
A receiver that is not a dictionary but has a member of these names
called with a string (a HashSet<word>, ...) goes into NOT_DICTIONARIES.

--check <reference.md>: the reference's entry names are the backticked
names in the first cell of its table rows (`| `name` | ...`). Fails
(exit 1) when
  - a name the code reads is not one of them (missing),
  - one of them is neither read by the code nor listed in PASS_THROUGH
    (stale),
  - a non-literal lookup is unreviewed, or (default paths only) a
    REVIEWED or CONSTRUCTOR_READS item matches no code.
"""

import argparse
import os
import re
import sys
import textwrap

TOP = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    '..', '..'))
DEFAULT_ROOTS = ['src', 'applications/solvers', 'applications/utilities']
DEFAULT_PATHS = [os.path.join(TOP, r) for r in DEFAULT_ROOTS]

# Dictionary member functions whose first argument is the entry's key
METHODS = (
    'getCheckOrDefault', 'getCheck', 'getOrDefault', 'getOrAdd', 'get',
    'lookupOrAddDefault', 'lookupOrDefault', 'lookupEntryPtr', 'lookupEntry',
    'lookup', 'readIfPresent', 'readEntry', 'found', 'optionalSubDict',
    'subOrEmptyDict', 'subDict', 'isDict', 'findDict', 'findEntry',
    'getModelProperty',
)

# Receivers that are not dictionaries (argList: command-line options;
# choices: an Enum; neighbours: a list of processors)
NOT_DICTIONARIES = {'args', 'choices', 'neighbours'}

# Project helpers that read the entries named by their literal arguments
HELPERS = (
    'readPositive', 'readFinite', 'readPoisson', 'readParcelScalar',
    'readScalar', 'readLabel', 'oneOf', 'readChoice',
)

# Reviewed lookups whose key is not a string literal:
#   (file name, key text as written) -> (names read, why)
# names: the entry names this lookup reads ([] if none: not a dictionary,
# or a helper's parameter whose call sites are scanned as helpers).
REVIEWED = {
    ('chargedFoamAdvisor.C', '"rho." + phase'):
        (['rho.<continuousPhase>'], 'the carrier gas density of a'
             ' chargedDPMFoam case (transportProperties)'),
    # --- helpers: the key is the helper's parameter; the literal keys of
    #     the helper's calls are scanned (HELPERS, the `get` lambda)
    ('checkedEntry.H', 'key'):
        ([], 'getChecked/getCheckedOrDefault/getPositive(OrDefault)(dict,'
             ' key, ...): helpers, calls scanned'),
    ('ExplicitParcelInjection.C', 'key'):
        ([], 'readParcelScalar(dict, i, key, ...): helper, calls scanned'),
    ('RaseraTriboCharging.C', 'key'):
        ([], 'lambda get(dict, key, positive): helper, calls scanned'),
    ('periodicElectrostatics.C', 'key'):
        ([], 'readLabel/readScalar(dict, key, ...): helpers, calls scanned'),
    ('triboParameters.C', 'key'):
        ([], 'readFinite/readPositive/readPoisson(dict, key): helpers'),
    ('triboParameters.C', 'a'):
        ([], 'oneOf(dict, a, b, optional): helper, calls scanned'),
    ('triboParameters.C', 'b'):
        ([], 'oneOf(dict, a, b, optional): helper, calls scanned'),
    ('MeshPoisson.C', 'key'):
        (['radius', 'rCut'], 'checkedCoeffs: the charge shape radius of'
             ' meshPoissonCoeffs, range-checked before meshPoisson reads it'),
    # --- keys built at run time
    ('particleMaterials.C', 'names[m]'):
        ([], 'constantProperties/materials/<material>: the user\'s material'
             ' names, each a dictionary of rho0, youngsModulus, poissonsRatio'),
    ('EllipsoidCollision.C', 'materials.name(m)'):
        ([], 'walls/<material>: a material\'s own e, mu, rollingFriction'),
    ('RaseraTriboCharging.C', 'materials.name(m)'):
        ([], 'particles/<material> and walls/<patch>/<material>: a'
             ' material\'s own kappaC, workFunction, Gamma'),
    ('ElectrostaticsModel.C', 'type + "Coeffs"'):
        ('electrostaticsCoeffs',
         '<type>Coeffs of the electrostatics model (added empty if absent):'
         ' one name per electrostaticsModel type'),
    ('ElectrostaticsSurvey.C', 'caseType + "Coeffs"'):
        ([], "the case's own <type>Coeffs (electrostaticsCoeffs, documented"
             " per type), copied as a candidate"),
    ('ElectrostaticsSurvey.C', 'type + "Coeffs"'):
        ([], 'a candidate\'s <type>Coeffs: its solveInterval'),
    ('ElectrostaticsSurvey.C', 'farType + "Coeffs"'):
        ([], 'the recommended far field\'s <type>Coeffs, to which the'
             ' near-field candidates add their nearField'),
    ('ElectrostaticsSurvey.C', 'e.keyword()'):
        ([], 'compares the entries of two coefficient dictionaries'),
    ('meshPoisson.C', 'Phi_.name()'):
        (['Phi'], 'system/fvSolution solvers/Phi must exist'),
    ('RaseraTriboCharging.C', 'name'):
        ([], 'walls.findDict(<wall patch name>, REGEX): the keys are patch'
             ' names or regular expressions, not entry names'),
    # --- not dictionaries
    ('ImageCoulomb.C', 'patchi'): ([], 'DynamicList<label>::found'),
    ('BemNearField.C', 'id'):
        ([], 'a set of parcel ids'),
    ('InducedDipoleNearField.C', 'labelPair(p.origProc(), p.origId())'):
        ([], 'a set of parcel ids'),
    ('inducedDipole.C', 'labelPair(min(i, j), max(i, j))'):
        ([], 'a set of index pairs'),
}

# Entries that the reference documents although the project's code does
# not look them up by name: OpenFOAM reads them for the project's models.
#   name -> why
PASS_THROUGH = {
    # cloudProperties structure (KinematicCloud, cloudSolution)
    'solution': 'cloudSolution: the cloud dictionary holding the entries of'
                ' EllipsoidCloud (trackingTolerance, ...)',
    'maxCo': 'cloudSolution: tracking Courant number (EllipsoidCloud'
             ' checks its range through solution().maxCo())',
    'subModels': 'KinematicCloud: the dictionary of the model selections',
    'cloudFunctions': 'KinematicCloud: cloud function objects'
                      ' (particleHistory)',
    'collisionModel': 'CollidingCloud: selects ellipsoidCollision',
    'particleForces': 'KinematicCloud: holds oscillatingFrame, ellipsoidDrag',
    'injectionModels': 'KinematicCloud: holds explicitParcels',
    'SOI': 'OpenFOAM InjectionModel: start of injection of explicitParcels',
    # <type>Coeffs of run-time selected project models whose coefficient
    # dictionary OpenFOAM's CloudSubModelBase/subModelBase reads (required)
    'GammaKappaCoeffs': 'subModelBase: coefficients of triboChargingModel'
                        ' GammaKappa',
    'workFunctionCoeffs': 'subModelBase: coefficients of triboChargingModel'
                          ' workFunction',
    'ellipsoidCollisionCoeffs': 'subModelBase: coefficients of'
                                ' collisionModel ellipsoidCollision',
}

# Entries read through a constructor that takes the dictionary (no lookup
# call to scan): (file name, anchor text that must be in the file) -> names
CONSTRUCTOR_READS = {
    ('createFields.H', 'IOobject::groupName("rho", continuousPhaseName)'):
        (['rho.<continuousPhase>'],
         'dimensionedScalar(groupName("rho", phase), dimDensity,'
         ' transportProperties) in chargedDPMFoam'),
}


# ----------------------------------------------------------------------------

def strip_comments(text):
    """Blank out // and /* */ comments, keep strings and line numbers."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == '/' and i + 1 < n and text[i + 1] == '/':
            j = text.find('\n', i)
            j = n if j < 0 else j
            out.append(' ')
            i = j
        elif c == '/' and i + 1 < n and text[i + 1] == '*':
            j = text.find('*/', i + 2)
            j = n if j < 0 else j + 2
            out.append(' ' + re.sub(r'[^\n]', '', text[i:j]))
            i = j
        elif c == '"' or c == "'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            out.append(text[i:j + 1])
            i = j + 1
        else:
            out.append(c)
            i += 1
    return ''.join(out)


def call_args(text, start):
    """The argument text of the call whose '(' is at start, and its end."""
    depth = 0
    i = start
    n = len(text)
    while i < n:
        c = text[i]
        if c == '"':
            j = i + 1
            while j < n and text[j] != '"':
                j += 2 if text[j] == '\\' else 1
            i = j
        elif c in '([{':
            depth += 1
        elif c in ')]}':
            depth -= 1
            if depth == 0:
                return text[start + 1:i], i
        i += 1
    return text[start + 1:], n


def split_args(args):
    """Top-level comma split."""
    parts, depth, cur, i = [], 0, [], 0
    while i < len(args):
        c = args[i]
        if c == '"':
            j = i + 1
            while j < len(args) and args[j] != '"':
                j += 2 if args[j] == '\\' else 1
            cur.append(args[i:j + 1])
            i = j + 1
            continue
        if c in '([{<':
            depth += 1 if c != '<' else 0
        if c in ')]}':
            depth -= 1
        if c == ',' and depth == 0:
            parts.append(''.join(cur).strip())
            cur = []
        else:
            cur.append(c)
        i += 1
    if ''.join(cur).strip():
        parts.append(''.join(cur).strip())
    return parts


STRING = re.compile(r'"((?:[^"\\]|\\.)*)"')
LITERAL_ONLY = re.compile(r'^\s*"((?:[^"\\]|\\.)*)"\s*$')
METHOD_CALL = re.compile(
    r'(?:\.|->)\s*(?:template\s+)?'
    r'(?P<name>' + '|'.join(METHODS) + r')\b\s*(?:<[^()";{}]*>)?\s*(?=\()')
RECEIVER = re.compile(r'([A-Za-z_]\w*)\s*(?:\(\s*\))?\s*$')
HELPER_CALL = re.compile(
    r'(?<![\w.>:])(?P<name>' + '|'.join(HELPERS) + r'|get)\s*(?=\()')
KEYED_HELPER_CALL = re.compile(
    r'(?<![\w.>:])(?P<name>getChecked|getCheckedOrDefault|getPositive'
    r'|getPositiveOrDefault)\s*'
    r'(?:<[^<>()]*>)?\s*(?=\()')
FUNCTION1_CALL = re.compile(r'Function1\s*<[^<>]*>\s*::\s*New\s*(?=\()')
WORD_CONST = re.compile(
    r'\bword\s+(?P<id>[A-Za-z_]\w*)\s*(?:\(|=)(?P<init>[^;]*);')
TYPENAME = re.compile(r'\bTypeName\s*\(\s*"(\w+)"\s*\)')


class Read:
    def __init__(self, name, path, line, how):
        self.name, self.path, self.line, self.how = name, path, line, how


def source_files(paths):
    files = []
    for p in paths:
        # relative paths: to the working directory, else to the project
        if not os.path.isabs(p) and not os.path.exists(p):
            p = os.path.join(TOP, p)
        p = os.path.abspath(p)
        if not os.path.exists(p):
            sys.exit('dictionaryEntries.py: no such file or directory: ' + p)
        if os.path.isfile(p):
            files.append(p)
            continue
        for root, dirs, names in os.walk(p):
            dirs[:] = sorted(d for d in dirs
                             if d not in ('lnInclude', 'Make')
                             and not d.startswith('.'))
            for f in sorted(names):
                if f.endswith(('.C', '.H')):
                    files.append(os.path.join(root, f))
    return files


def electrostatics_types(files):
    """TypeNames of the electrostatics models (none included: noneCoeffs
    holds the near field of a scene without a far field; not the base or
    the near-field layer): their <type>Coeffs are read by
    ElectrostaticsModel."""
    types = set()
    for f in files:
        if ('/Electrostatics/' in f and '/NearField/' not in f
                and '/ElectrostaticsModel/' not in f):
            with open(f, errors='replace') as fh:
                types.update(TYPENAME.findall(fh.read()))
    return sorted(types)


def rel(path):
    r = os.path.relpath(path, TOP)
    return path if r.startswith('..') else r


def extract(paths):
    """(reads, warnings, used REVIEWED keys, stale CONSTRUCTOR_READS)"""
    files = source_files(paths)
    reads, warnings, used = [], [], set()
    constructor_found = set()
    for path in files:
        with open(path, errors='replace') as fh:
            raw = fh.read()
        text = strip_comments(raw)
        base = os.path.basename(path)

        def line_of(pos):
            return text.count('\n', 0, pos) + 1

        words = {}
        for m in WORD_CONST.finditer(text):
            lits = STRING.findall(m.group('init'))
            if lits:
                words.setdefault(m.group('id'), set()).update(lits)

        # 1, 3, 4: dictionary member calls
        for m in METHOD_CALL.finditer(text):
            recv = RECEIVER.search(text, max(0, m.start() - 80), m.start())
            if recv and recv.group(1) in NOT_DICTIONARIES:
                continue
            args, _ = call_args(text, m.end())
            parts = split_args(args)
            if not parts:
                continue        # iter.found() etc.
            key = parts[0]
            line = line_of(m.start('name'))
            lit = LITERAL_ONLY.match(key)
            if lit:
                reads.append(Read(lit.group(1), path, line, m.group('name')))
            elif re.fullmatch(r'[A-Za-z_]\w*', key) and key in words:
                for w in sorted(words[key]):
                    reads.append(Read(w, path, line,
                                      m.group('name') + ' (word ' + key + ')'))
            elif (base, key) in REVIEWED:
                used.add((base, key))
                names = REVIEWED[(base, key)][0]
                if names == 'electrostaticsCoeffs':
                    names = [t + 'Coeffs' for t in electrostatics_types(
                        source_files(DEFAULT_PATHS) + files)]
                for w in names:
                    reads.append(Read(w, path, line,
                                      m.group('name') + ' (reviewed)'))
            else:
                warnings.append((path, line, m.group('name'), key))

        # Enum<...>::lookupOrDefault("key", dict, ...) is caught above (the
        # receiver is the Enum); 2: helpers and Function1
        for m in HELPER_CALL.finditer(text):
            args, _ = call_args(text, m.end())
            line = line_of(m.start())
            # declarations/definitions have typed parameters, no literals
            for lit in STRING.findall(args):
                if m.group('name') == 'get' and len(split_args(args)) != 3:
                    continue
                reads.append(Read(lit, path, line, m.group('name')))
        for m in KEYED_HELPER_CALL.finditer(text):
            args, _ = call_args(text, m.end())
            parts = split_args(args)
            lit = LITERAL_ONLY.match(parts[1]) if len(parts) > 1 else None
            if lit:
                reads.append(Read(lit.group(1), path, line_of(m.start()),
                                  m.group('name')))
        for m in FUNCTION1_CALL.finditer(text):
            args, _ = call_args(text, m.end())
            parts = split_args(args)
            lit = LITERAL_ONLY.match(parts[0]) if parts else None
            if lit:
                reads.append(Read(lit.group(1), path, line_of(m.start()),
                                  'Function1::New'))

        for (fname, anchor), (names, why) in CONSTRUCTOR_READS.items():
            if base == fname and anchor in text:
                constructor_found.add((fname, anchor))
                for w in names:
                    reads.append(Read(w, path, line_of(text.find(anchor)),
                                      'constructor'))

    return reads, warnings, used, constructor_found


def reference_names(md):
    """Backticked names in the first cell of the table rows of md."""
    names = {}
    with open(md) as fh:
        for i, line in enumerate(fh, 1):
            s = line.strip()
            if not s.startswith('|'):
                continue
            cells = s.strip('|').split('|')
            if not cells or re.fullmatch(r'[\s:-]*', cells[0]):
                continue
            for n in re.findall(r'`([^`]+)`', cells[0]):
                names.setdefault(n, i)
    return names


def main():
    ap = argparse.ArgumentParser(
        description=textwrap.dedent(__doc__.split('\n\n')[1]).strip(),
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument('paths', nargs='*',
                    help='C++ files or directories (default: %s)'
                    % ' '.join(DEFAULT_ROOTS))
    ap.add_argument('--check', metavar='REFERENCE',
                    help='check the reference (markdown) against the code')
    ap.add_argument('--sites', action='store_true',
                    help='list every read with file:line')
    ap.add_argument('--count', action='store_true',
                    help='print the number of names and of read sites only')
    opts = ap.parse_args()

    paths = opts.paths or DEFAULT_PATHS
    reads, warnings, used, ctor = extract(paths)
    names = sorted({r.name for r in reads})

    if opts.count:
        print('%d names %d sites' % (len(names), len(reads)))
        return 0

    if warnings:
        print('WARNING: %d lookup(s) with a key that is not a string literal'
              ' and not in REVIEWED (add them to REVIEWED in %s):'
              % (len(warnings), rel(os.path.abspath(__file__))))
        for path, line, how, key in warnings:
            print('    %s:%d: %s(%s)' % (rel(path), line, how, key))

    if not opts.check:
        if opts.sites:
            for r in sorted(reads, key=lambda r: (r.name.lower(), r.path,
                                                   r.line)):
                print('%-28s %s:%d %s' % (r.name, rel(r.path), r.line, r.how))
        else:
            for n in names:
                print(n)
        print('%d names, %d read sites, %d unreviewed non-literal lookups'
              % (len(names), len(reads), len(warnings)), file=sys.stderr)
        return 0

    ref = reference_names(opts.check)
    failed = False

    missing = [n for n in names if n not in ref]
    if missing:
        failed = True
        print('MISSING: %d entr%s the code reads, not in %s:'
              % (len(missing), 'y' if len(missing) == 1 else 'ies',
                 opts.check))
        for n in missing:
            sites = ['%s:%d' % (rel(r.path), r.line)
                     for r in reads if r.name == n]
            print('    %-28s %s' % (n, ' '.join(sites[:3])))

    stale = sorted(n for n in ref if n not in names and n not in PASS_THROUGH)
    if stale:
        failed = True
        print('STALE: %d name%s in %s that the code does not read (and not'
              ' in PASS_THROUGH):' % (len(stale), '' if len(stale) == 1
                                      else 's', opts.check))
        for n in stale:
            print('    %-28s line %d' % (n, ref[n]))

    if warnings:
        failed = True

    # REVIEWED and CONSTRUCTOR_READS items whose code is gone (only for the
    # default tree: a partial scan does not see every file)
    if not opts.paths:
        gone = [k for k in REVIEWED if k not in used]
        gone += [k for k in CONSTRUCTOR_READS if k not in ctor]
        if gone:
            failed = True
            print('STALE REVIEW: %d item(s) of REVIEWED/CONSTRUCTOR_READS'
                  ' match no code:' % len(gone))
            for fname, key in gone:
                print('    %s: %s' % (fname, key))

    print('%d names read by the code (%d read sites), %d names in the'
          ' reference, %d missing, %d stale, %d unreviewed lookups'
          % (len(names), len(reads), len(ref), len(missing), len(stale),
             len(warnings)))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
