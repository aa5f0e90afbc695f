# etc/bashrc: uses a sourced OpenFOAM of API 1912, refuses any other API,
# and says what to do without a prepared tree or without apt.
. "$(dirname "$0")/common.sh.inc"
bashrc="$top/etc/bashrc"

# A clean shell: only what a login shell would have
clean() { env -i HOME="$HOME" PATH=/usr/local/bin:/usr/bin:/bin "$@"; }

# 1. The cached tree: OpenFOAM + project on PATH
out=$(clean bash -c ". '$bashrc' && command -v chargedParticleFoam && command -v wmake && echo \"\$FOAM_API|\$WM_PROJECT_VERSION|\$CHARGEDFOAM_DIR\"" 2>&1)
check environment.cachedTree "($(echo "$out" | tail -1))" \
    grep -q "platforms/.*/bin/chargedParticleFoam" <<< "$out"

# 2. An OpenFOAM v1912 the user sourced first is kept
tree=$(clean bash -c ". '$bashrc' && echo \$WM_PROJECT_DIR")
out=$(clean bash -c ". '$tree/etc/bashrc' WM_MPLIB=SYSTEMOPENMPI; before=\$WM_PROJECT_DIR; . '$bashrc' && echo \"kept:\$before:\$WM_PROJECT_DIR\"" 2>&1)
check environment.sourced1912 "($(echo "$out" | tail -1))" \
    grep -q "^kept:$tree:$tree$" <<< "$out"

# 3. Another API is refused with a message
fake="$work/OpenFOAM-v2306"
mkdir -p "$fake/bin"
printf '#!/bin/sh\necho 2306\n' > "$fake/bin/foamEtcFile"
chmod +x "$fake/bin/foamEtcFile"
out=$(clean WM_PROJECT_DIR="$fake" bash -c ". '$bashrc'; echo rc=\$?" 2>&1)
check environment.otherApi "($(echo "$out" | head -1))" \
    grep -q "API '2306'.*needs OpenFOAM v1912" <<< "$out"
check environment.otherApiFails "(returns non-zero)" grep -q "rc=1" <<< "$out"

# 4. No prepared tree: says to run etc/setup
out=$(clean CHARGEDFOAM_CACHE="$work/emptyCache" bash -c ". '$bashrc'; echo rc=\$?" 2>&1)
check environment.noTree "($(echo "$out" | head -1))" \
    grep -q "run '.*etc/setup' once" <<< "$out"

# 5. Neither apt nor OpenFOAM: says what to install
out=$(env -i HOME="$HOME" PATH="$work/noApt" CHARGEDFOAM_CACHE="$work/emptyCache" \
    /bin/bash -c ". '$bashrc'; echo rc=\$?" 2>&1)
check environment.noApt "($(echo "$out" | head -1))" \
    grep -q "neither apt nor a sourced OpenFOAM.*" <<< "$out"
check environment.noAptFails "(returns non-zero)" grep -q "rc=1" <<< "$out"

# 6. etc/setup refuses another sourced API too
out=$(clean WM_PROJECT_DIR="$fake" "$top/etc/setup" 2>&1)
check environment.setupOtherApi "($(echo "$out" | tail -1))" \
    grep -q "has API 2306" <<< "$out"
