# ParaView pictures (etc/paraview/render) as the tutorials' Allrun makes them:
# - aggregateCollision (point charges only): a neutral prolate hits an
#   aggregate of a +q and a -q prolate. The picture is not empty, the charge
#   colour range is min..max of q read from the case, and the pixels at the
#   +q and -q parcels (projected with the camera the sidecar reports) are
#   shades of the colour map's two ends (a swapped or wrong colouring fails);
# - chargedDuct shortened to 2 ms (serial): 2000 ellipsoids and the mesh
#   field Phi on a slice, whose colour range is min..max of Phi;
# - twoChargedSpheres run on 2 processors with only processor*/ kept: the
#   renderer reads the decomposed case;
# - a case without parcels is refused with a message.
# ParaView is installed by the renderer on first use (etc/setup --paraview).
. "$(dirname "$0")/common.sh.inc"
render="$top/etc/paraview/render"

# pictureChecks <case> <name> [extremes]: the PASS/FAIL lines of the picture
# of <case> (<case>/<case basename>.png and .render.json); 'extremes' adds the
# colours at the extreme parcels
pictureChecks()
{
    $PY - "$top/etc/python" "$@" <<'PYEOF'
import json, os, sys
import numpy as np
import matplotlib.image as mpimg
sys.path.insert(0, sys.argv[1])
from foamLagrangian import read_field, read_internal_field, read_positions

case, name = sys.argv[2], sys.argv[3]
extremes = len(sys.argv) > 4
def check(ok, what, detail):
    print("%s: paraviewPicture.%s.%s (%s)" % ("PASS" if ok else "FAIL", name, what, detail))

base = os.path.join(case, os.path.basename(os.path.abspath(case)))
info = json.load(open(base + ".render.json"))
img = mpimg.imread(base + ".png")[..., :3].astype(float)   # RGB in [0, 1]
H, W = img.shape[:2]

# (a) not empty: above the colour bars and axes (the bottom 200 rows), coloured
# pixels (parcels, field; the domain is grey) in many shades
scene = img[:H - 200]
chroma = scene.max(axis=2) - scene.min(axis=2)
coloured = int((chroma > 0.15).sum())
colours = len(np.unique((scene*31).round().reshape(-1, 3), axis=0))
check(coloured >= 200 and colours > 50 and [W, H] == [info["image"]["width"], info["image"]["height"]],
      "notEmpty", "%dx%d; above the bottom 200 rows (bars, axes) %d coloured pixels (>= 200), %d distinct colours (> 50)"
      % (W, H, coloured, colours))

# (b) the charge colour range is the data's min..max of q (float32 in ParaView)
cloud = os.path.join(info["case"], info["timeName"], "lagrangian", info["cloud"])
if info["decomposed"]:
    procs = sorted(d for d in os.listdir(info["case"]) if d.startswith("processor"))
    files = [os.path.join(info["case"], p, info["timeName"], "lagrangian", info["cloud"])
             for p in procs]
    q = np.concatenate([read_field(os.path.join(f, "q")) for f in files if os.path.isdir(f)])
else:
    q = read_field(os.path.join(cloud, "q"))
lo, hi = info["q"]["colorRange"]
scale = max(abs(q.min()), abs(q.max()))
err = max(abs(lo - q.min()), abs(hi - q.max()))/scale
check(err < 1e-6 and q.max() > q.min() and info["nParcels"] == len(q), "chargeRange",
      "colour range %.6g .. %.6g C, q of %d parcels %.6g .. %.6g C, relative difference %.1e < 1e-6"
      % (lo, hi, len(q), q.min(), q.max(), err))

# the colour bar shows the map's ends (its last texels: within 8/255)
ends = [np.array(info["q"][k]) for k in ("colorMin", "colorMax")]
n = [int((np.abs(img - c).max(axis=2) < 8/255).sum()) for c in ends]
check(min(n) >= 10, "colourBarEnds", "pixels within 8/255 of the min and max colours: %d, %d (>= 10)"
      % tuple(n))

if info["field"]:
    f = info["field"]
    v = read_internal_field(os.path.join(info["case"], info["timeName"], f["name"]))
    if v.ndim == 2:
        v = np.linalg.norm(v, axis=1)
    err = max(abs(f["range"][0] - v.min()), abs(f["range"][1] - v.max()))/max(abs(v).max(), 1e-300)
    check(err < 1e-6, "fieldRange", "%s colour range %.6g .. %.6g, cells %.6g .. %.6g, relative difference %.1e"
          % (f["label"], f["range"][0], f["range"][1], v.min(), v.max(), err))

if extremes:
    # (c) the pixels at the parcels of min and max q have the colours of the
    # map's ends: shades (white lights, no specular) keep the RGB direction
    X = read_positions(os.path.join(cloud, "positions"))
    axes = read_field(os.path.join(cloud, "semiAxes"))
    cam = info["camera"]
    f0, p0 = np.array(cam["focalPoint"]), np.array(cam["position"])
    d = (f0 - p0)/np.linalg.norm(f0 - p0)
    right = np.cross(d, cam["viewUp"]); right /= np.linalg.norm(right)
    up = np.cross(right, d)
    pxPerM = 0.5*H/cam["parallelScale"]
    unit = lambda c: c/np.linalg.norm(c)
    yy, xx = np.mgrid[0:H, 0:W]
    for which, i, own, other in (("min", q.argmin(), ends[0], ends[1]),
                                 ("max", q.argmax(), ends[1], ends[0])):
        u = 0.5*W + pxPerM*np.dot(X[i] - f0, right)
        v = 0.5*H - pxPerM*np.dot(X[i] - f0, up)
        r = max(1.5, min(6.0, 0.5*pxPerM*info["glyph"]["scale"]*np.min(axes[i])))
        disc = img[(xx - u)**2 + (yy - v)**2 <= r*r]
        cosOwn = (disc @ unit(own))/np.maximum(np.linalg.norm(disc, axis=1), 1e-9)
        cosOther = (disc @ unit(other))/np.maximum(np.linalg.norm(disc, axis=1), 1e-9)
        share = float(((cosOwn > 0.99) & (cosOwn > cosOther)).mean()) if len(disc) else 0.0
        check(share > 0.8, "colourAt%sQ" % which.capitalize(),
              "parcel %d, q = %.4g C, at pixel (%.0f, %.0f): %.0f %% of %d pixels within r = %.1f px "
              "are shades of the %s-end colour %s (> 80 %%)"
              % (i, q[i], u, v, 100*share, len(disc), r, which, np.round(own, 3).tolist()))
PYEOF
}

# 1. aggregateCollision, point charges (both velocities; the Allrun renders)
copyCase aggregateCollision "$work/aggregate"
cd "$work/aggregate" || exit 1
./Allrun pointCharges > log.Allrun 2>&1
c=runs/pointCharges-v0.16
check paraviewPicture.aggregate.allrun "(Allrun renders each run: png, pvsm, render.json; see log.render)" \
    test -s runs/pointCharges-v0.02/pointCharges-v0.02.png -a -s $c/pointCharges-v0.16.png \
         -a -s $c/pointCharges-v0.16.pvsm -a -s $c/pointCharges-v0.16.render.json
[ -s $c/pointCharges-v0.16.render.json ] && pictureChecks $c aggregate extremes
grep -h '^render:' log.render

# a case without parcels (the tutorial's root: mesh, no time folders)
"$render" . > log.noParcels 2>&1
rc=$?
check paraviewPicture.noParcels "(status $rc = 3 and 'no lagrangian data' in the message)" \
    bash -c "[ $rc = 3 ] && grep -q 'no lagrangian data' log.noParcels"

# 2. chargedDuct, 2 ms in serial: 2000 ellipsoids and Phi
copyCase chargedDuct "$work/duct"
cd "$work/duct" || exit 1
./Allrun -serial 0.002 > log.Allrun 2>&1
check paraviewPicture.duct.allrun "(Allrun renders duct.png with Phi; see log.render)" \
    bash -c "test -s duct.png && grep -q '\"name\": \"Phi\"' duct.render.json"
[ -s duct.render.json ] && pictureChecks . duct
grep -h '^render:' log.render

# 3. twoChargedSpheres on 2 processors, reconstructed times removed
copyCase twoChargedSpheres "$work/decomposed"
cd "$work/decomposed" || exit 1
./Allrun -parallel > log.Allrun 2>&1
rm -rf 0.0* decomposed.png decomposed.render.json
"$render" . > log.renderDecomposed 2>&1
check paraviewPicture.decomposed.render "(processor* only: rendered, sidecar says decomposed)" \
    bash -c "test -s decomposed.png && grep -q '\"decomposed\": true' decomposed.render.json"
[ -s decomposed.render.json ] && pictureChecks . decomposed
grep -h '^render:' log.renderDecomposed
