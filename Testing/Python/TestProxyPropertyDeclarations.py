"""pvpython: every BoolSurf proxy's properties are exactly those of the checked-in expectation.

Shared properties are declared once (XML/Shared, expanded when the plugin is configured) and
the one-step BoolSurf filter takes its stages' declarations: this test guards that what
ParaView builds from them does not change. For each proxy of the plugin (filters, sources,
writers; not the representations, which carry ParaView's own properties) it lists

- every property by name, with its class and its default values on a new proxy;
- the proxy's collapsed XML definition as ParaView sees it (properties in declaration order
  with every attribute, their domains, hints and property groups), without the
  <Documentation> text;

and compares the lot with Testing/Data/ProxyProperties.txt. A change to a property's name,
default, domain, visibility or order fails here. After an intended change, run with
BOOLSURF_UPDATE_EXPECTATION=1 to rewrite the file, and review its diff.
"""
import difflib
import os
import sys
import tempfile
import xml.etree.ElementTree as ET

from paraview import servermanager as sm
from paraview.simple import LoadPlugin

plugin = os.environ["BOOLSURF_PLUGIN"]
source_dir = os.environ["BOOLSURF_SOURCE_DIR"]
expectation = os.path.join(source_dir, "Testing", "Data", "ProxyProperties.txt")
LoadPlugin(plugin, remote=False, ns=globals())
pxm = sm.ProxyManager().SMProxyManager
definitions = pxm.GetProxyDefinitionManager()


def as_tree(xml):
    """A vtkPVXMLElement as an ElementTree element (PrintXML writes to the C++ stdout)."""
    sys.stdout.flush()
    saved = os.dup(1)
    with tempfile.TemporaryFile() as f:
        os.dup2(f.fileno(), 1)
        xml.PrintXML()
        os.dup2(saved, 1)
        os.close(saved)
        f.seek(0)
        return ET.fromstring(f.read())


def attributes(element):
    return " ".join("%s=%r" % item for item in sorted(element.attrib.items()))


def describe(element, depth, lines):
    if element.tag == "Documentation":
        return
    lines.append("  " * depth + element.tag + " " + attributes(element))
    for child in element:
        describe(child, depth + 1, lines)


def describe_values(proxy, lines):
    properties = proxy.NewPropertyIterator()
    properties.Begin()
    while not properties.IsAtEnd():
        p = properties.GetProperty()
        line = "  property %s %s" % (properties.GetKey(), p.GetClassName())
        if p.IsA("vtkSMVectorProperty") and not p.IsA("vtkSMProxyProperty"):
            values = [p.GetElement(i) for i in range(p.GetNumberOfElements())]
            line += " values=%r" % (values,)
        lines.append(line)
        properties.Next()


def describe_plugin():
    lines = []
    it = definitions.NewIterator()
    it.GoToFirstItem()
    while not it.IsDoneWithTraversal():
        group, name = it.GetGroupName(), it.GetProxyName()
        it.GoToNextItem()
        xml = definitions.GetCollapsedProxyDefinition(group, name, None, False)
        if xml is None or "BoolSurf" not in (xml.GetAttribute("class") or ""):
            continue
        if group == "representations":
            continue
        tree = as_tree(xml)
        lines.append("proxy %s/%s %s" % (group, name, attributes(tree)))
        describe_values(pxm.NewProxy(group, name), lines)
        for child in tree:
            describe(child, 1, lines)
    return lines


actual = describe_plugin()
if os.environ.get("BOOLSURF_UPDATE_EXPECTATION"):
    with open(expectation, "w", encoding="utf-8") as f:
        f.write("\n".join(actual) + "\n")
    print("wrote %s (%d lines)" % (expectation, len(actual)))
    sys.exit(0)
with open(expectation, encoding="utf-8") as f:
    expected = f.read().splitlines()
if actual != expected:
    sys.stdout.writelines(line + "\n" for line in difflib.unified_diff(
        expected, actual, "Testing/Data/ProxyProperties.txt", "the plugin", lineterm=""))
    sys.exit("the proxies' properties differ from Testing/Data/ProxyProperties.txt")
print("%d lines of property declarations as expected" % len(actual))
