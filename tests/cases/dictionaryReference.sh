# doc/reference.md documents every dictionary entry the code reads:
# tests/tools/dictionaryEntries.py extracts the entry names the C++ code of
# src, applications/solvers and applications/utilities reads (literal keys,
# keys through helpers and word constants, reviewed non-literal keys) and
# compares them with the names in the first column of the reference's
# tables. Checks: (a) none is missing, (b) none is stale (in the reference,
# read nowhere) and no non-literal lookup is unreviewed, (c) the extractor
# is not vacuous: it finds most of the 155 names counted when the
# reference was written, and reports an entry planted in a copy of a
# source file as missing, a row planted in a copy of the reference as
# stale, and a planted non-literal lookup as unreviewed. No build, no run:
# a few seconds.
. "$(dirname "$0")/common.sh.inc"

tool="$tools/dictionaryEntries.py"
ref="$top/doc/reference.md"
roots="$top/src $top/applications/solvers $top/applications/utilities"

# (a), (b): the reference against the code
$PY "$tool" --check "$ref" > check.log 2>&1
rc=$?
summary=$(tail -1 check.log)
# the tool ran to its summary (a crash exits 1 too)
ran() { grep -q 'names read by the code' "$1"; }
nMissing=$(grep -c '^    ' <(sed -n '/^MISSING/,/^[A-Z]/p' check.log))
if ran check.log && [ "$rc" -le 1 ] && ! grep -q '^MISSING' check.log
then
    pass "dictionaryReference.allDocumented ($summary)"
else
    fail "dictionaryReference.allDocumented ($nMissing missing, exit $rc; see $work/check.log)"
    sed -n '/^MISSING/,/^[A-Z]/p' check.log | head -40
fi
if ran check.log && [ "$rc" -le 1 ] && ! grep -Eq '^(STALE|WARNING)' check.log
then
    pass "dictionaryReference.noStale (no stale names, no unreviewed lookups)"
else
    fail "dictionaryReference.noStale (exit $rc; see $work/check.log)"
    grep -A20 -E '^(STALE|WARNING)' check.log | head -40
fi

# (c1) not vacuous: 155 names (248 read sites) when the reference was
# written; at least 90 % of them
count=$($PY "$tool" --count)
nNames=${count%% names*}
if [ "${nNames:-0}" -ge 140 ] 2>/dev/null
then
    pass "dictionaryReference.extractorCount ($count; >= 140 names)"
else
    fail "dictionaryReference.extractorCount ($count; expected >= 140 names)"
fi

# (c2) an entry planted in a copy of a source file is reported missing,
# and is the only one (the copy reads nothing else new)
src="$top/src/chargedParticles/clouds/Templates/ChargedCloud/ChargedCloud.C"
mkdir -p planted
sed '/readIfPresent("rho0"/i\    dict.getOrDefault<scalar>("plantedEntryForTest", 1);' \
    "$src" > planted/ChargedCloud.C
$PY "$tool" --check "$ref" $roots planted/ChargedCloud.C \
    > planted.log 2>&1
rc=$?
missing=$(sed -n '/^MISSING/,/^[A-Z]/p' planted.log | grep '^    ' | awk '{print $1}' | tr '\n' ' ')
if grep -q 'plantedEntryForTest' planted/ChargedCloud.C \
    && ran planted.log && [ "$rc" -eq 1 ] \
    && [ "$missing" = "plantedEntryForTest " ]
then
    pass "dictionaryReference.plantedEntry (reported missing: $missing; exit $rc)"
else
    fail "dictionaryReference.plantedEntry (exit $rc, missing: '$missing'; see $work/planted.log)"
fi

# (c3) a row planted in a copy of the reference is reported stale
sed 's/^| `rho0` |/| `plantedStaleEntry` | scalar | - | - | - | planted |\n&/' \
    "$ref" > reference.md
$PY "$tool" --check reference.md > stale.log 2>&1
rc=$?
stale=$(sed -n '/^STALE:/,/^[A-Z]/p' stale.log | grep '^    ' | awk '{print $1}' | tr '\n' ' ')
if ran stale.log && [ "$rc" -eq 1 ] && [ "$stale" = "plantedStaleEntry " ]
then
    pass "dictionaryReference.plantedStale (reported stale: $stale; exit $rc)"
else
    fail "dictionaryReference.plantedStale (exit $rc, stale: '$stale'; see $work/stale.log)"
fi

# (c4) a lookup with a non-literal key is reported until reviewed
sed '/readIfPresent("rho0"/i\    dict.get<scalar>(plantedKeyForTest);' \
    "$src" > planted/ChargedCloudKey.C
$PY "$tool" --check "$ref" $roots planted/ChargedCloudKey.C \
    > key.log 2>&1
rc=$?
if ran key.log && [ "$rc" -eq 1 ] && grep -q 'ChargedCloudKey.C:[0-9]*: get(plantedKeyForTest)' key.log
then
    pass "dictionaryReference.plantedNonLiteral ($(grep -m1 'plantedKeyForTest' key.log | sed 's/^ *//'); exit $rc)"
else
    fail "dictionaryReference.plantedNonLiteral (exit $rc; see $work/key.log)"
fi
