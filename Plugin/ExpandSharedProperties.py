#!/usr/bin/env python3
"""Writes the plugin's server-manager XML with the shared property declarations expanded.

    ExpandSharedProperties.py <output folder> <shared.xml>... -- <filter.xml>...

A property that several filters have (GeodesicMethod, Resolution, ...) is declared once, in
XML/Shared/*.xml; a filter's XML takes it where its panel wants it with

    <SharedProperty name="GeodesicMethod"/>

Attributes given there beside `name` are added to the shared declaration's opening tag (or
replace the same attribute), a nested <Documentation> replaces the shared one, and nested
<Hints> replace the shared ones or, when it has none, are added as its last element:

    <SharedProperty name="Resolution" panel_visibility="advanced">
      <Documentation>As in Trace Surface Curves (Bezier subdivision levels).</Documentation>
    </SharedProperty>

ParaView 5.11's own sharing, proxy inheritance (base_proxygroup/base_proxyname), takes every
property of one base proxy and puts them before the proxy's own: it cannot give a filter a
subset of the trace settings, nor keep them where its panel has them. The expansion is
textual, so the written XML is the file as it was written with the declaration in place of
the marker; each output is checked to parse. Files are rewritten only when they change.
"""
import os
import re
import sys
import xml.etree.ElementTree as ET

MARKER = re.compile(r"^([ \t]*)<SharedProperty\b([^>]*?)(?:/>|>(.*?)</SharedProperty>)",
                    re.S | re.M)
DECLARATION = re.compile(
    r"^([ \t]*)<(\w+Property)\b[^>]*?\bname=\"([^\"]+)\"[^>]*?(?:/>|>.*?</\2>)", re.S | re.M)
ATTRIBUTE = re.compile(r"([\w:]+)=\"([^\"]*)\"")
DOCUMENTATION = re.compile(r"<Documentation\b.*?</Documentation>", re.S)
HINTS = re.compile(r"<Hints\b.*?</Hints>", re.S)


def fail(message):
    sys.exit("ExpandSharedProperties: " + message)


def read_declarations(paths):
    """Name -> declaration text, its first line's indentation removed from every line."""
    declarations = {}
    for path in paths:
        with open(path, encoding="utf-8") as f:
            text = f.read()
        ET.fromstring(text)  # a shared file must be well-formed XML itself
        for match in DECLARATION.finditer(text):
            indent, name = match.group(1), match.group(3)
            if name in declarations:
                fail("%s: property %s is declared twice" % (path, name))
            lines = match.group(0).split("\n")
            declarations[name] = "\n".join(
                line[len(indent):] if line.startswith(indent) else line for line in lines)
    return declarations


def with_attribute(declaration, key, value):
    """The declaration with attribute `key` of its opening tag set to `value`."""
    end = declaration.index(">")
    if declaration[end - 1] == "/":
        end -= 1
    tag = declaration[:end]
    pattern = re.compile(r"\b%s=\"[^\"]*\"" % re.escape(key))
    if pattern.search(tag):
        tag = pattern.sub('%s="%s"' % (key, value), tag, count=1)
    else:
        tag = '%s %s="%s"' % (tag, key, value)
    return tag + declaration[end:]


def with_hints(declaration, hints, indent):
    """The declaration with its <Hints> element replaced by `hints`, or `hints` added before
    its closing tag (one indentation step inside it) when it has none."""
    if HINTS.search(declaration):
        return HINTS.sub(lambda _: hints, declaration, count=1)
    closing = declaration.rindex("</")
    if declaration[:closing].endswith("/"):
        fail("a property without elements cannot take hints")
    line_start = declaration.rindex("\n", 0, closing) + 1
    return (declaration[:line_start] + indent + "  " + hints + "\n" +
            declaration[line_start:])


def expand(text, declarations, path):
    def replace(match):
        indent, attributes, body = match.group(1), match.group(2), match.group(3) or ""
        overrides = dict(ATTRIBUTE.findall(attributes))
        name = overrides.pop("name", None)
        if name not in declarations:
            fail("%s: no shared declaration of property %r" % (path, name))
        declaration = declarations[name]
        for key, value in overrides.items():
            declaration = with_attribute(declaration, key, value)
        declaration = "\n".join(indent + line if line else line
                                for line in declaration.split("\n"))
        documentation = DOCUMENTATION.search(body)
        if documentation:
            if not DOCUMENTATION.search(declaration):
                fail("%s: %s has no shared documentation to replace" % (path, name))
            declaration = DOCUMENTATION.sub(lambda _: documentation.group(0), declaration,
                                            count=1)
        hints = HINTS.search(body)
        if hints:
            declaration = with_hints(declaration, hints.group(0), indent)
        return declaration

    return MARKER.sub(replace, text)


def main(argv):
    if "--" not in argv or len(argv) < 4:
        fail(__doc__)
    split = argv.index("--")
    output, shared, sources = argv[1], argv[2:split], argv[split + 1:]
    declarations = read_declarations(shared)
    os.makedirs(output, exist_ok=True)
    for path in sources:
        with open(path, encoding="utf-8") as f:
            text = expand(f.read(), declarations, path)
        try:
            ET.fromstring(text)
        except ET.ParseError as error:
            fail("%s expanded is not well-formed: %s" % (path, error))
        target = os.path.join(output, os.path.basename(path))
        if os.path.exists(target):
            with open(target, encoding="utf-8") as f:
                if f.read() == text:
                    continue
        with open(target, "w", encoding="utf-8") as f:
            f.write(text)


if __name__ == "__main__":
    main(sys.argv)
