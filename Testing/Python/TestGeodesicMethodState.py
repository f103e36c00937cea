"""pvpython: the GeodesicMethod property (Bounded 0, Exact 1, Locally shortest 2) and the
deprecated ExactGeodesics property it replaces, through state files and scripts.

(a) A state saved with GeodesicMethod = Exact (and Locally shortest) loads back with it.
(b) An old state file (no GeodesicMethod element, ExactGeodesics 0) loads as Locally shortest;
    ExactGeodesics 1 there is the old default and loads as today's default.
(c) Scripts that set ExactGeodesics on a proxy still work: 0 is Locally shortest, 1 Exact.
(d) A state that holds both with different values loads with GeodesicMethod's: ParaView
    pushes a proxy's modified properties in the order of their names, and ExactGeodesics comes
    before GeodesicMethod; a new proxy gets the XML defaults in declaration order, so
    ExactGeodesics (default 1) is declared before GeodesicMethod (default 0, Bounded).

The method is checked on the proxy and on the VTK object the server-manager pushed it to."""
import os
import shutil
import sys
import xml.etree.ElementTree as ET

import boolsurf  # noqa: F401 (the filters' Python wrapping: GetClientSideObject() is typed)
from paraview.simple import *  # noqa: F401,F403
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scratch  # noqa: E402

BOUNDED, EXACT, LOCALLY_SHORTEST = 0, 1, 2
NAMES = {BOUNDED: "Bounded", EXACT: "Exact", LOCALLY_SHORTEST: "Locally shortest"}
# Proxies with the deprecated ExactGeodesics property, and those with GeodesicMethod only.
WITH_SWITCH = ("TraceSurfaceCurves", "BoolSurf")
METHOD_ONLY = ("BoolSurfSurfaceCurves", "ResolveInconsistentShapes")

plugin = os.environ["BOOLSURF_PLUGIN"]
source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
folder = scratch.folder("boolsurf-geodesic-method-")


def load_plugin():
    LoadPlugin(plugin, remote=False, ns=globals())


def build_pipeline(**method):
    """The mesh, a drawing and every filter with the method property, each given `method`
    (GeodesicMethod=... or ExactGeodesics=...; the drawing and Resolve take GeodesicMethod
    only)."""
    mesh = PLYReader(registrationName="mesh",
                     FileNames=[os.path.join(source_dir, "Data", "eight.ply")])
    # A small triangle inside triangle 10 of the genus-2 eight (null-homologous).
    only_method = {k: v for k, v in method.items() if k == "GeodesicMethod"}
    drawing = SurfaceCurves(registrationName="drawing", Surface=mesh, Points=[0.0] * 9,
                            TriangleIds=[10, 10, 10],
                            Barycentrics=[0.1, 0.1, 0.8, 0.1, 0.1, 0.8], **only_method)
    TraceSurfaceCurves(registrationName="trace", Surface=mesh, Curves=drawing, **method)
    BoolSurf(registrationName="one", Surface=mesh, Curves=drawing, ShapeA=0, ShapeB=0,
             **method)
    ResolveInconsistentShapes(registrationName="resolve", Surface=mesh, Curves=drawing,
                              **only_method)


def proxies():
    """The filters with the property, by XML name (one each)."""
    found = {}
    for proxy in GetSources().values():
        name = proxy.GetXMLName()
        if name in WITH_SWITCH + METHOD_ONLY:
            assert name not in found, name
            found[name] = proxy
    assert sorted(found) == sorted(WITH_SWITCH + METHOD_ONLY), sorted(found)
    return found


def expect(expected, what, names=WITH_SWITCH + METHOD_ONLY, proxy_shows_it=True):
    """Every proxy in `names` runs `expected` (its VTK object's GeodesicMethod) and, when
    `proxy_shows_it`, shows it in its GeodesicMethod property. A method given through the
    deprecated ExactGeodesics property (a script, an old state file) is pushed to the VTK
    object but leaves the proxy's GeodesicMethod as it was."""
    for name, proxy in proxies().items():
        if name not in names:
            continue
        proxy.UpdatePipeline()
        vtk_object = proxy.GetClientSideObject()
        assert vtk_object.GetGeodesicMethod() == expected, (
            what, name, "VTK object", NAMES.get(vtk_object.GetGeodesicMethod()), NAMES[expected])
        if name in WITH_SWITCH:
            assert vtk_object.GetExactGeodesics() == (expected == EXACT), (what, name)
        if proxy_shows_it:
            assert proxy.GetProperty("GeodesicMethod").GetData() == NAMES[expected], (
                what, name, proxy.GetProperty("GeodesicMethod").GetData(), NAMES[expected])


def save(name):
    path = os.path.join(folder, name)
    SaveState(path)
    return path


def reload(path):
    ResetSession()
    load_plugin()
    LoadState(path)


def edit_state(path, name, exact=None, method=None, drop_method=False):
    """A copy of the state file at `path` with, in every proxy with ExactGeodesics, that value
    set to `exact`, GeodesicMethod set to `method` or its element dropped."""
    tree = ET.parse(path)
    edited = 0
    for proxy in tree.getroot().iter("Proxy"):
        if proxy.get("group") != "filters" or proxy.get("type") not in WITH_SWITCH:
            continue
        for prop in list(proxy.findall("Property")):
            if prop.get("name") == "GeodesicMethod":
                if drop_method:
                    proxy.remove(prop)
                elif method is not None:
                    prop.find("Element").set("value", str(method))
            elif prop.get("name") == "ExactGeodesics" and exact is not None:
                prop.find("Element").set("value", str(exact))
        edited += 1
    assert edited == len(WITH_SWITCH), edited
    out = os.path.join(folder, name)
    tree.write(out)
    return out


load_plugin()

# A new proxy starts with the default, Bounded, on its VTK object too (the XML defaults are
# pushed in declaration order: ExactGeodesics 1 (Exact), then GeodesicMethod 0).
build_pipeline()
expect(BOUNDED, "new proxies")
# The enumeration's entries, as the GUI lists them.
domain = proxies()["TraceSurfaceCurves"].GetProperty("GeodesicMethod").SMProperty.GetDomain("enum")
entries = [(domain.GetEntryText(i), domain.GetEntryValue(i))
           for i in range(domain.GetNumberOfEntries())]
assert entries == [("Bounded", 0), ("Exact", 1), ("Locally shortest", 2)], entries
# The old property is hidden from the panel.
for name in WITH_SWITCH:
    assert proxies()[name].GetProperty("ExactGeodesics").SMProperty.GetPanelVisibility() == \
        "never", name

# (a) A state file keeps the method.
for method in (EXACT, LOCALLY_SHORTEST, BOUNDED):
    ResetSession()
    load_plugin()
    build_pipeline(GeodesicMethod=NAMES[method])
    expect(method, "set")
    reload(save("method-%d.pvsm" % method))
    expect(method, "state (a)")

# (b) An old state file: ExactGeodesics only.
ResetSession()
load_plugin()
build_pipeline(GeodesicMethod="Exact")
new_state = save("new.pvsm")
reload(edit_state(new_state, "old-off.pvsm", exact=0, drop_method=True))
expect(LOCALLY_SHORTEST, "old state, ExactGeodesics 0 (b)", WITH_SWITCH, proxy_shows_it=False)
# ExactGeodesics 1 was the old default, saved in every old state file: it cannot be told
# from a choice, and such files load with today's default.
reload(edit_state(new_state, "old-on.pvsm", exact=1, drop_method=True))
expect(BOUNDED, "old state, ExactGeodesics 1 (b)", WITH_SWITCH)

# (c) Scripts setting the deprecated property, at creation and afterwards.
ResetSession()
load_plugin()
build_pipeline(ExactGeodesics=0)
expect(LOCALLY_SHORTEST, "script", WITH_SWITCH, proxy_shows_it=False)
for name in WITH_SWITCH:
    proxies()[name].ExactGeodesics = 1
expect(EXACT, "script", WITH_SWITCH, proxy_shows_it=False)
for name in WITH_SWITCH:
    proxies()[name].ExactGeodesics = 0
expect(LOCALLY_SHORTEST, "script", WITH_SWITCH, proxy_shows_it=False)
# Such a session saved and loaded again keeps what the VTK objects had.
reload(save("script-off.pvsm"))
expect(LOCALLY_SHORTEST, "script, saved", WITH_SWITCH, proxy_shows_it=False)
# The property set afterwards takes over.
for name in WITH_SWITCH:
    proxies()[name].GeodesicMethod = "Exact"
expect(EXACT, "set after the switch", WITH_SWITCH)

# (d) Both in one state file, with different values: GeodesicMethod wins.
reload(edit_state(new_state, "both-0-1.pvsm", exact=0, method=EXACT))
expect(EXACT, "both: ExactGeodesics 0, GeodesicMethod Exact (d)", WITH_SWITCH)
reload(edit_state(new_state, "both-1-2.pvsm", exact=1, method=LOCALLY_SHORTEST))
expect(LOCALLY_SHORTEST, "both: ExactGeodesics 1, GeodesicMethod Locally shortest (d)",
       WITH_SWITCH)
reload(edit_state(new_state, "both-0-0.pvsm", exact=0, method=BOUNDED))
# GeodesicMethod 0 is its default, so it is not pushed: the switch decides (this is what a
# session saved after a script set ExactGeodesics = 0 holds, see (c)).
expect(LOCALLY_SHORTEST, "both: ExactGeodesics 0, GeodesicMethod Bounded (d)", WITH_SWITCH,
       proxy_shows_it=False)
shutil.rmtree(folder)
print("GeodesicMethod state and script compatibility: ok")
