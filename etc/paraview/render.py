"""ParaView picture of chargedFoam cases (pvbatch; run it through
etc/paraview/render, whose header lists the options): the parcels as
ellipsoids of their true size and orientation coloured by charge, the far
walls and feature edges of the domain and, where the case writes one, the
mesh field (Phi, else |E|) on a semi-transparent mid-plane slice.

For each case it writes, beside the case:
  <case>/<name>.png          the picture (<name>: the case folder's name)
  <case>/<name>.pvsm         the same view for the GUI:
                                 paraview --state=<case>/<name>.pvsm
                             (it holds the absolute path of the case's
                             .foam file; for a moved case, choose "Search
                             files under specified directory" = the case in
                             ParaView's load-state dialogue)
  <case>/<name>.render.json  what was drawn: time, parcels, charge colour
                             range and end colours, field and its range,
                             camera (read by tests/cases/paraviewPicture.sh)

Ellipsoids: the lagrangian field 'shape' is R diag(a, b, c) R^T (semi-axes,
rotation body -> inertial; EllipsoidParcelIO.C), so a Tensor Glyph of a unit
sphere on it, scale factor 1, is the ellipsoid itself (checked: every glyph
vertex of 300 randomly oriented parcels lies on the ellipsoid given by
semiAxes and orientationEps/Eta to 7e-6, float precision). Parcels without
'shape' are drawn as spheres of diameter d.

Charge colours: the colour range is the data range [min q, max q] at that
time, coloured as the diverging 'Cool to Warm' map over [-max|q|, max|q|]
would colour them (blue negative, pale neutral, red positive), so a colour
means the same sign in every picture. All charges equal: q0 -+ 1 %
(-+ 1e-18 C if q0 = 0). White lights and no specular highlight: each parcel
pixel is a shade of its colour.

Camera (parallel projection): up against constant/g (else z), looking across
the shorter horizontal side from 20 degrees above and to the side; it fits
the domain, or the parcels' region when they would be under 6 pixels across
the whole domain. Parcels still under 8 pixels are enlarged by a round
factor (at most to a third of their mean spacing), said in the title.
"""
import argparse
import json
import math
import os
import re
import sys
import time

import numpy as np
from paraview.simple import (
    ColorBy, CreateRenderView, ExtractSurface, FeatureEdges, GetAnimationScene,
    GetColorTransferFunction, GetScalarBar, Glyph, OpenFOAMReader,
    ResetSession, SaveScreenshot, SaveState, SetActiveView, Show, Slice,
    TensorGlyph, Text, Transform, servermanager)
from paraview.vtk.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkRenderingCore import vtkColorTransferFunction

FIELD_UNITS = {"Phi": "V", "E": "V/m", "U": "m/s", "p": "Pa"}


class RenderError(Exception):
    pass


def die(msg):
    raise RenderError(msg)


def say(fd, line):
    """A line to the process's stdout (fd 1) or stderr (2) directly:
    pvbatch's Python streams do not reach a redirected stdout unless
    PYTHONUNBUFFERED is set, and the script ends with os._exit"""
    os.write(fd, (line + "\n").encode())


def is_time(name):
    try:
        float(name)
        return True
    except ValueError:
        return False


def lagrangian_times(root):
    """{time name: [clouds]} of the time folders of root holding a cloud
    (a lagrangian/<cloud>/positions file)."""
    out = {}
    if not os.path.isdir(root):
        return out
    for t in os.listdir(root):
        lag = os.path.join(root, t, "lagrangian")
        if is_time(t) and os.path.isdir(lag):
            clouds = sorted(c for c in os.listdir(lag)
                            if os.path.isfile(os.path.join(lag, c, "positions")))
            if clouds:
                out[t] = clouds
    return out


def case_layout(case):
    """(decomposed?, {time: clouds}) for the case: reconstructed results are
    used when there are any, else the processor folders'."""
    times = lagrangian_times(case)
    if times:
        return False, times
    procs = sorted(d for d in os.listdir(case) if re.fullmatch(r"processor\d+", d))
    for p in procs:
        for t, clouds in lagrangian_times(os.path.join(case, p)).items():
            times.setdefault(t, [])
            times[t] = sorted(set(times[t]) | set(clouds))
    return bool(times), times


def field_class(path):
    """The class word of an OpenFOAM field file's header, or None."""
    try:
        with open(path, errors="replace") as f:
            head = f.read(2000)
    except OSError:
        return None
    m = re.search(r"\bclass\s+(\w+)\s*;", head)
    return m.group(1) if m else None


def nice_ceil(x):
    """The smallest of 1, 2, 5, 10, 20, ... not below x."""
    k = 10**math.floor(math.log10(x))
    for m in (1, 2, 5, 10):
        if m*k >= x*(1 - 1e-12):
            return m*k
    return 10*k


def nice_floor(x):
    """The largest of 1, 2, 5, 10, 20, ... not above x (at least 1)."""
    if x <= 1:
        return 1.0
    k = 10**math.floor(math.log10(x))
    return max(m*k for m in (1, 2, 5) if m*k <= x*(1 + 1e-12))


def gravity_up(case):
    """Unit vector against constant/g, or None when there is none or g = 0."""
    try:
        text = open(os.path.join(case, "constant", "g")).read()
        m = re.search(r"value\s*\(([^)]*)\)", text)
        g = np.array(m.group(1).split(), dtype=float)
    except (OSError, AttributeError, ValueError):
        return None
    n = np.linalg.norm(g)
    return -g/n if n > 0 else None


def leaves(data):
    """Non-empty datasets of a (possibly composite) data object."""
    if data.IsA("vtkCompositeDataSet"):
        it = data.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            d = it.GetCurrentDataObject()
            if d.GetNumberOfPoints() > 0:
                yield d
            it.GoToNextItem()
    elif data.GetNumberOfPoints() > 0:
        yield data


def point_array(data, name):
    arrays = [vtk_to_numpy(d.GetPointData().GetArray(name))
              for d in leaves(data) if d.GetPointData().GetArray(name)]
    return np.concatenate(arrays) if arrays else None


def cool_to_warm():
    """A callable: value in [0, 1] -> RGB of ParaView's 'Cool to Warm'
    (Moreland's diverging map; built here so the state has no extra map)."""
    ctf = vtkColorTransferFunction()
    ctf.SetColorSpaceToDiverging()
    ctf.AddRGBPoint(0.0, 0.231373, 0.298039, 0.752941)
    ctf.AddRGBPoint(1.0, 0.705882, 0.0156863, 0.14902)
    return lambda s: rgb(ctf, s)


def rgb(vtkLut, x):
    c = [0.0, 0.0, 0.0]
    vtkLut.GetColor(float(x), c)
    return c


def charge_lut(qmin, qmax):
    """Colour range and RGB points for the charges (see the header)."""
    if qmax > qmin:
        lo, hi = qmin, qmax
    else:
        delta = 0.01*abs(qmin) if qmin != 0 else 1e-18
        lo, hi = qmin - delta, qmin + delta
    Q = max(abs(lo), abs(hi))
    ref = cool_to_warm()
    points = []
    for x in np.linspace(lo, hi, 33):
        points += [float(x)] + ref(0.5 + 0.5*x/Q)
    return lo, hi, points


def camera_frame(bounds, up):
    """Camera axes for the box: screen up (against gravity if the case has
    one, else z), looking across the shorter horizontal side of the box from
    20 degrees above and 20 degrees to the side, the longer horizontal side
    running left to right. Returns (direction to the camera, view up, slice
    normal axis)."""
    size = np.array([bounds[1] - bounds[0], bounds[3] - bounds[2],
                     bounds[5] - bounds[4]])
    if up is None:
        up = np.array([0.0, 0.0, 1.0])
    u = int(np.argmax(np.abs(up)))
    upAxis = np.zeros(3)
    upAxis[u] = math.copysign(1.0, up[u])
    horizontal = [i for i in range(3) if i != u]
    f, s = sorted(horizontal, key=lambda i: (size[i], i))
    fHat, sHat = np.eye(3)[f], np.eye(3)[s]
    # camera on the side of f from which s runs to the right
    sigma = -np.dot(np.cross(fHat, upAxis), sHat)
    el, az = math.radians(20), math.radians(20)
    toCamera = (math.cos(el)*(math.cos(az)*sigma*fHat + math.sin(az)*sHat)
                + math.sin(el)*upAxis)
    return toCamera/np.linalg.norm(toCamera), upAxis, f


def fit_view(box, toCamera, viewUp, args):
    """Picture size and parallel-projection camera showing the box between
    the title (top) and the colour bars (bottom)."""
    right = np.cross(-toCamera, viewUp)
    right /= np.linalg.norm(right)
    screenUp = np.cross(right, -toCamera)
    corners = np.array([[x, y, z] for x in box[0:2] for y in box[2:4]
                        for z in box[4:6]])
    centre = 0.5*(corners.min(axis=0) + corners.max(axis=0))
    w = max(np.ptp(corners @ right), 1e-12)
    h = max(np.ptp(corners @ screenUp), 1e-12)
    top, bottom = 50, 130
    W = args.width or (1200 if w >= 0.8*h else 900)
    H = args.height or int(min(900, max(500, W*h/w*1.08 + top + bottom)))
    worldPerPx = max(w*1.08/W, h*1.06/(H - top - bottom))
    focal = centre - screenUp*0.5*(bottom - top)*worldPerPx
    position = focal + toCamera*(4*max(w, h) + np.ptp(corners @ toCamera))
    return {"W": W, "H": H, "worldPerPx": worldPerPx, "focal": focal, "box": box,
            "position": position, "parallelScale": 0.5*H*worldPerPx}


def render_case(caseArg, args, one):
    t0 = time.time()
    case = os.path.abspath(caseArg)
    if not os.path.isdir(case):
        die(f"{caseArg}: no such case folder")
    name = os.path.basename(case)
    decomposed, times = case_layout(case)
    if not times:
        die(f"{case}: no lagrangian data (no <time>/lagrangian/<cloud>/positions, "
            "nor in processor*/): run the case first, with parcels written at a "
            "write time")
    if args.time is None:
        tName = max(times, key=float)
    else:
        tName = min(times, key=lambda t: abs(float(t) - args.time))
        if abs(float(tName) - args.time) > 1e-9*max(1.0, abs(args.time)):
            die(f"{case}: no lagrangian data at time {args.time} "
                f"(times with parcels: {' '.join(sorted(times, key=float))})")
    clouds = times[tName]
    cloud = args.cloud or clouds[0]
    if cloud not in clouds:
        die(f"{case}: no cloud '{cloud}' at time {tName} (clouds: {' '.join(clouds)})")
    tValue = float(tName)
    timeDir = os.path.join(case, "processor0" if decomposed else "", tName)

    # The mesh field: Phi, else |E|, else none (or the one asked for)
    field, component = None, None
    want = args.field
    if want == "auto":
        for cand, comp in (("Phi", None), ("E", "Magnitude")):
            if field_class(os.path.join(timeDir, cand)):
                field, component = cand, comp
                break
    elif want != "none":
        cand = "E" if want == "magE" else want
        cls = field_class(os.path.join(timeDir, cand))
        if not cls or not cls.startswith("vol"):
            die(f"{case}: no volume field '{cand}' at time {tName}")
        field = cand
        component = None if cls == "volScalarField" else "Magnitude"

    # the case's own .foam file (tutorials touch <tutorial>.foam), else one
    foams = sorted(f for f in os.listdir(case) if f.endswith(".foam"))
    foam = os.path.join(case, name + ".foam" if name + ".foam" in foams or not foams
                        else foams[0])
    if not os.path.exists(foam):
        open(foam, "a").close()

    caseType = "Decomposed Case" if decomposed else "Reconstructed Case"
    mesh = OpenFOAMReader(registrationName=os.path.basename(foam) + " (mesh)",
                          FileName=foam)
    mesh.CaseType = caseType
    mesh.UpdatePipelineInformation()
    mesh.SkipZeroTime = 0
    mesh.MeshRegions = ["internalMesh"]
    mesh.CellArrays = [field] if field else []
    mesh.LagrangianArrays = []
    mesh.Createcelltopointfiltereddata = 1
    mesh.UpdatePipeline(tValue)

    lag = OpenFOAMReader(registrationName=os.path.basename(foam) + " (" + cloud + ")",
                         FileName=foam)
    lag.CaseType = caseType
    lag.SkipZeroTime = 0
    lag.MeshRegions = ["lagrangian/" + cloud]
    lag.CellArrays = []
    lag.UpdatePipelineInformation()     # the arrays of the case type chosen
    avail = list(lag.LagrangianArrays.Available)
    if "q" not in avail:
        die(f"{case}: cloud '{cloud}' has no charge field q")
    useShape = "shape" in avail
    if not useShape and "d" not in avail:
        die(f"{case}: cloud '{cloud}' has neither 'shape' nor 'd' to size the parcels")
    lag.LagrangianArrays = [a for a in ("q", "shape", "d") if a in avail]
    lag.UpdatePipeline(tValue)

    lagData = servermanager.Fetch(lag)
    q = point_array(lagData, "q")
    if q is None or q.size == 0:
        die(f"{case}: no parcels read at time {tName}")
    q = q.astype(float)
    nParcels = int(q.size)
    if useShape:
        sh = point_array(lagData, "shape").astype(float)   # XX YY ZZ XY YZ XZ
        T = np.empty((len(sh), 3, 3))
        T[:, 0, 0], T[:, 1, 1], T[:, 2, 2] = sh[:, 0], sh[:, 1], sh[:, 2]
        T[:, 0, 1] = T[:, 1, 0] = sh[:, 3]
        T[:, 1, 2] = T[:, 2, 1] = sh[:, 4]
        T[:, 0, 2] = T[:, 2, 0] = sh[:, 5]
        aMax = np.linalg.eigvalsh(T).max(axis=1)        # largest semi-axis
    else:
        aMax = 0.5*point_array(lagData, "d").astype(float)

    # the mesh's bounds and the field's cell range, without fetching the mesh
    meshInfo = mesh.GetDataInformation()
    bounds = list(meshInfo.GetBounds())
    if meshInfo.GetNumberOfCells() == 0 or bounds[1] < bounds[0]:
        die(f"{case}: no mesh read (constant/polyMesh)")
    fieldRange = None
    if field:
        if field not in mesh.CellData.keys():
            die(f"{case}: field '{field}' not read at time {tName}")
        fieldRange = list(mesh.CellData[field].GetRange(-1 if component else 0))

    # ---- camera, picture size and ellipsoid enlargement
    toCamera, viewUp, sliceAxis = camera_frame(bounds, gravity_up(case))
    centre = 0.5*np.array([bounds[0] + bounds[1], bounds[2] + bounds[3],
                           bounds[4] + bounds[5]])
    aTyp = float(np.median(aMax))
    frame = fit_view(bounds, toCamera, viewUp, args)
    zoomed = False
    if args.view == "parcels" or (args.view == "auto" and 2*aTyp/frame["worldPerPx"] < 6):
        # parcels too small with the whole domain: fit their region instead
        X = np.concatenate([vtk_to_numpy(d.GetPoints().GetData())
                            for d in leaves(lagData)]).astype(float)
        lo = X.min(axis=0) - aMax.max()
        hi = X.max(axis=0) + aMax.max()
        grow = 0.08*np.linalg.norm(hi - lo) + 1.5*aMax.max()
        lo = np.maximum(lo - grow, bounds[0::2])
        hi = np.minimum(hi + grow, bounds[1::2])
        frame = fit_view([lo[0], hi[0], lo[1], hi[1], lo[2], hi[2]],
                         toCamera, viewUp, args)
        zoomed = True
    W, H, worldPerPx = frame["W"], frame["H"], frame["worldPerPx"]
    if args.scale == "auto":
        px = 2*aTyp/worldPerPx
        scale = 1.0 if px >= 8 else nice_ceil(12/px)
        # a dense cloud: no more than a third of the mean spacing
        box = np.array(frame["box"][1::2]) - np.array(frame["box"][0::2])
        spacing = (np.prod(np.maximum(box, 1e-12))/nParcels)**(1/3)
        while scale > 1 and 2*aTyp*scale > spacing/3:
            scale = nice_floor(scale*0.99)
    else:
        scale = float(args.scale)

    # ---- view
    view = CreateRenderView()
    SetActiveView(view)
    view.ViewSize = [W, H]
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.OrientationAxesVisibility = 1
    view.OrientationAxesLabelColor = [0.0, 0.0, 0.0]
    view.CameraParallelProjection = 1
    view.EnableRenderOnInteraction = 0
    view.DepthPeeling = 1
    # white lights: a pixel is a shade of its colour-map colour
    view.KeyLightWarmth = view.FillLightWarmth = 0.5
    view.BackLightWarmth = view.HeadLightWarmth = 0.5
    view.ViewTime = tValue
    scene = GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    scene.AnimationTime = tValue

    # domain: the far walls (front faces culled: nothing between camera and
    # parcels) and the feature edges
    boundary = ExtractSurface(registrationName="boundary", Input=mesh)
    # moved away from the camera by 0.3 % of the domain (unchanged on the
    # picture: parallel projection), so the edges are not dotted by them
    farWalls = Transform(registrationName="walls", Input=boundary)
    farWalls.Transform = "Transform"
    diagonal = math.dist(bounds[0::2], bounds[1::2])
    farWalls.Transform.Translate = list(-0.003*diagonal*toCamera)
    walls = Show(farWalls, view)
    walls.ColorArrayName = ["POINTS", ""]
    walls.AmbientColor = walls.DiffuseColor = [1.0, 1.0, 1.0]
    walls.Ambient, walls.Diffuse = 0.8, 0.2     # pale: the parcels stand out
    walls.BackfaceRepresentation = "Cull Frontface"
    edges = FeatureEdges(registrationName="domain edges", Input=boundary)
    edges.FeatureAngle = 30
    edges.BoundaryEdges = 1
    edges.NonManifoldEdges = 0
    edges.Coloring = 0
    ed = Show(edges, view)
    ed.ColorArrayName = ["POINTS", ""]
    ed.AmbientColor = ed.DiffuseColor = [0.15, 0.15, 0.15]
    ed.LineWidth = 2.0

    # field on the mid-plane normal to the shorter horizontal side, behind
    # half of the parcels: semi-transparent so those behind still show
    fieldInfo = None
    if field:
        sl = Slice(registrationName="mid-plane", Input=mesh)
        sl.SliceType = "Plane"
        sl.SliceType.Origin = list(centre)
        sl.SliceType.Normal = list(np.eye(3)[sliceAxis])
        sd = Show(sl, view)
        if component:
            ColorBy(sd, ("POINTS", field, component))
        else:
            ColorBy(sd, ("POINTS", field))
        fLut = GetColorTransferFunction(field)
        fLut.ApplyPreset("Viridis (matplotlib)", True)
        lo, hi = fieldRange
        if hi <= lo:
            d = 0.01*abs(lo) if lo != 0 else 1e-12
            lo, hi = lo - d, hi + d
        fLut.RescaleTransferFunction(lo, hi)
        fLut.AutomaticRescaleRangeMode = "Never"
        sd.Opacity = 0.6
        sd.Ambient, sd.Diffuse = 1.0, 0.0      # flat colours: the map, not the light
        units = FIELD_UNITS.get(field.split(".")[0], "")
        label = (field + " magnitude" if component else field) + (" [%s]" % units if units else "")
        fb = GetScalarBar(fLut, view)
        fieldBar = {"position": [0.59, 0.03], "length": 0.34}
        style_bar(fb, label, fieldBar, lo, hi)
        sd.SetScalarBarVisibility(view, True)
        fieldInfo = {"name": field, "component": component, "label": label,
                     "range": [lo, hi], "dataRange": fieldRange,
                     "sliceNormal": list(np.eye(3)[sliceAxis]),
                     "sliceOrigin": list(centre), "colorBar": fieldBar}

    # parcels
    if useShape:
        glyphs = TensorGlyph(registrationName="ellipsoids (shape)", Input=lag,
                             GlyphType="Sphere")
        glyphs.Tensors = ["POINTS", "shape"]
        glyphs.Scalars = ["POINTS", "q"]
        glyphs.ExtractEigenvalues = 1
        glyphs.ColorGlyphs = 1
        glyphs.Colorby = "input scalars"
        glyphs.LimitScalingByEigenvalues = 0
        glyphs.ScaleFactor = scale
        glyphs.GlyphType.Radius = 1.0
    else:
        glyphs = Glyph(registrationName="spheres (d)", Input=lag, GlyphType="Sphere")
        glyphs.ScaleArray = ["POINTS", "d"]
        glyphs.ScaleFactor = scale
        glyphs.GlyphMode = "All Points"
        glyphs.GlyphType.Radius = 0.5
    res = 24 if nParcels <= 3000 else 12
    glyphs.GlyphType.ThetaResolution = res
    glyphs.GlyphType.PhiResolution = max(8, 2*res//3)
    gd = Show(glyphs, view)
    ColorBy(gd, ("POINTS", "q"))
    qmin, qmax = float(q.min()), float(q.max())
    lo, hi, rgbPoints = charge_lut(qmin, qmax)
    qLut = GetColorTransferFunction("q")
    qLut.ColorSpace = "RGB"
    qLut.RGBPoints = rgbPoints
    qLut.AutomaticRescaleRangeMode = "Never"
    qLut.NanColor = [0.5, 0.0, 0.5]
    gd.Specular = 0.0          # keeps each pixel a shade of its charge colour
    qBar = {"position": [0.16, 0.03], "length": 0.34}
    style_bar(GetScalarBar(qLut, view), "charge q [C]", qBar, lo, hi)
    gd.SetScalarBarVisibility(view, True)

    title = "%s   t = %g s   %d parcel%s" % (name, tValue, nParcels,
                                             "" if nParcels == 1 else "s")
    if scale != 1:
        title += "   (ellipsoids drawn %gx enlarged)" % scale
    txt = Text(registrationName="title", Text=title)
    td = Show(txt, view)
    td.WindowLocation = "Upper Left Corner"
    td.FontSize = 20
    td.Color = [0.0, 0.0, 0.0]
    td.BackgroundColor = [1.0, 1.0, 1.0, 0.85]     # readable over a zoomed view

    view.CameraPosition = list(frame["position"])
    view.CameraFocalPoint = list(frame["focal"])
    view.CameraViewUp = list(viewUp)
    view.CameraParallelScale = frame["parallelScale"]
    view.CenterOfRotation = list(centre)

    png = os.path.abspath(args.output) if (one and args.output) else \
        os.path.join(case, name + ".png")
    SaveScreenshot(png, view, ImageResolution=[W, H], TransparentBackground=0)
    pvsm = os.path.join(case, name + ".pvsm")
    SaveState(pvsm)
    add_state_note(pvsm, name)

    lutObj = qLut.GetClientSideObject()
    info = {
        "case": case, "time": tValue, "timeName": tName, "cloud": cloud,
        "decomposed": decomposed, "nParcels": nParcels,
        "q": {"dataMin": qmin, "dataMax": qmax, "colorRange": [lo, hi],
              "colorMin": rgb(lutObj, lo), "colorMax": rgb(lutObj, hi),
              "colormap": "Cool to Warm over [-max|q|, max|q|], clipped to the range",
              "colorBar": qBar},
        "glyph": {"type": "tensor glyph of 'shape'" if useShape else "sphere of diameter d",
                  "scale": scale, "medianLargestSemiAxis": aTyp},
        "field": fieldInfo,
        "bounds": bounds,
        "image": {"file": png, "width": W, "height": H},
        "camera": {"position": list(frame["position"]),
                   "focalPoint": list(frame["focal"]), "viewUp": list(viewUp),
                   "parallelScale": frame["parallelScale"],
                   "parallelProjection": True,
                   "fits": "parcels" if zoomed else "domain"},
        "state": pvsm,
    }
    info["renderSeconds"] = round(time.time() - t0, 2)
    with open(os.path.join(case, name + ".render.json"), "w") as f:
        json.dump(info, f, indent=2)
    say(1, "render: %s  (t = %g s, %d parcels, q %.4g .. %.4g C%s%s; state %s; %.1f s)"
        % (os.path.relpath(png), tValue, nParcels, qmin, qmax,
           ", %s %.4g .. %.4g" % (fieldInfo["label"], *fieldInfo["range"]) if fieldInfo else "",
           ", ellipsoids x%g" % scale if scale != 1 else "",
           os.path.relpath(pvsm), time.time() - t0))
    ResetSession()


def style_bar(bar, title, where, lo, hi):
    bar.Title = title
    bar.ComponentTitle = ""
    bar.Orientation = "Horizontal"
    bar.WindowLocation = "Any Location"
    bar.Position = where["position"]
    bar.ScalarBarLength = where["length"]
    bar.ScalarBarThickness = 16
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.TitleFontSize = 18
    bar.LabelFontSize = 16
    bar.AutomaticLabelFormat = 0
    bar.RangeLabelFormat = "%-.3g"
    bar.AddRangeLabels = 1
    bar.DrawTickMarks = 1
    bar.DrawBackground = 1
    bar.BackgroundColor = [1.0, 1.0, 1.0, 0.85]
    # at most three inner labels, clear of the range labels at the ends
    step = nice_ceil((hi - lo)/4)
    big = max(abs(lo), abs(hi))
    if 1e-3 <= big < 1e5:
        bar.LabelFormat = "%%-.%df" % max(0, -math.floor(math.log10(step)))
    else:
        digits = int(math.floor(math.log10(big)) - math.floor(math.log10(step))) + 1
        bar.LabelFormat = "%%-.%de" % max(0, digits - 1)
    ticks = [k*step for k in range(math.ceil(lo/step), math.floor(hi/step) + 1)]
    bar.UseCustomLabels = 1
    bar.CustomLabels = [0.0 if abs(t) < 1e-9*step else t for t in ticks
                        if lo + 0.2*(hi - lo) < t < hi - 0.2*(hi - lo)]


def add_state_note(pvsm, name):
    """A comment at the top of the state file on how to open it."""
    note = ("<!-- chargedFoam picture of this case: open with\n"
            "         paraview --state=%s.pvsm\n"
            "     If the case moved, choose 'Search files under specified\n"
            "     directory' (the case) in ParaView's load-state dialogue. -->\n" % name)
    text = open(pvsm).read()
    if text.startswith("<?xml"):
        head, rest = text.split("\n", 1)
        text = head + "\n" + note + rest
    else:
        text = note + text
    open(pvsm, "w").write(text)


def main():
    p = argparse.ArgumentParser(prog="etc/paraview/render",
                                description=__doc__.split("\n\n")[0])
    p.add_argument("cases", nargs="+", metavar="caseDir")
    p.add_argument("--time", type=float, default=None,
                   help="time to draw (default: the latest with parcels)")
    p.add_argument("--field", default="auto",
                   help="Phi, magE, none, or a volume field (vectors: magnitude); "
                        "default: Phi, else |E|, else none")
    p.add_argument("--output", default=None,
                   help="picture file (one case only; default <case>/<name>.png)")
    p.add_argument("--scale", default="auto",
                   help="ellipsoid enlargement factor (default auto: 1 unless "
                        "they would be smaller than ~8 pixels)")
    p.add_argument("--view", default="auto", choices=("auto", "domain", "parcels"),
                   help="fit the domain or the parcels' region (default auto: "
                        "the domain unless the parcels would be tinier than 6 pixels)")
    p.add_argument("--cloud", default=None, help="cloud name (default: the first)")
    p.add_argument("--size", default=None, help="picture size WxH (default: from the domain)")
    def error(msg):
        p.print_usage(sys.stderr)
        die(msg)
    p.error = error
    args = p.parse_args()
    args.width = args.height = None
    if args.size:
        try:
            args.width, args.height = (int(v) for v in args.size.lower().split("x"))
        except ValueError:
            die("--size wants WxH, e.g. 1200x800")
    if args.output and len(args.cases) > 1:
        die("--output needs a single case")
    if args.scale != "auto":
        try:
            if float(args.scale) <= 0:
                raise ValueError
        except ValueError:
            die("--scale wants a positive number or auto")
    failed = 0
    for c in args.cases:
        try:
            render_case(c, args, len(args.cases) == 1)
        except RenderError as e:
            say(2, "render: ERROR: %s" % e)
            failed += 1
            ResetSession()
    return failed


try:
    status = 3 if main() else 0    # 3: the wrapper does not retry these
except RenderError as e:
    say(2, "render: ERROR: %s" % e)
    status = 3
sys.stdout.flush()
sys.stderr.flush()
os._exit(status)    # sys.exit after an error made pvbatch's X teardown fail
