#!/usr/bin/python3
"""The RatBez workbench's translations: finds every translatable string of the Mod folder, writes the
template RatBez/Resources/translations/RatBez.ts, brings each language file RatBez_<lang>.ts up to date
with it (keeping the translations it has, dropping strings the code no longer has) and compiles the .qm
files FreeCAD loads (lrelease, Debian's qttools5-dev-tools).

    /usr/bin/python3 freecad_workbench/update_translations.py [--check]

--check writes nothing and exits 1 when the template or a language file is not what the code asks for
(tests/freecad/test_translations.py runs it). Contexts, as FreeCAD's own modules use them:
  RatBez            the workbench's own texts: translate("...") and QT_TRANSLATE_NOOP("RatBez", "...")
  RatBez_<Command>  a command's menu text and tooltip (FreeCAD translates them in the command's name)
  App::Property     property tooltips (_tip) and the property editor's display of property and group names:
                    FreeCAD splits a name at its capitals ("MajorRadius" shows "Major Radius", the group
                    "RatBez" shows "Rat Bez") and then translates it in this context, which is how the
                    English file makes the group read "RatBez"
  Workbench         toolbar and menu names
Strings reach the panels through a few helpers with literal arguments (add_number("Angle"), LinkRow(...,
"Profile", ...)), class attributes (a command's menu and tooltip, a panel's TITLE and DIMENSIONS, the mode
tables) and loops over literal tuples whose elements are translated in the loop; the rules below find
those too. No line numbers are written, so moving code does not change the files.
"""

import argparse
import ast
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
MOD = os.path.join(HERE, "RatBez")
TRANSLATIONS = os.path.join(MOD, "Resources", "translations")
TEMPLATE = os.path.join(TRANSLATIONS, "RatBez.ts")
SOURCES = ["InitGui.py"] + [os.path.join("ratbez_wb", name) for name in
                            sorted(os.listdir(os.path.join(MOD, "ratbez_wb"))) if name.endswith(".py")]

CONTEXT = "RatBez"
PROPERTY = "App::Property"
# Property groups of the features (features.RatBezFeature.GROUP, SolidFeature's "Kernel").
GROUPS = ["RatBez", "Kernel"]
# Helpers whose literal arguments at these positions are translated in the RatBez context.
LABEL_ARGUMENTS = {"add_number": [0], "add_check": [0], "add_line_modes": [0], "add_vectors": [0], "LinkRow": [2]}
# Feature property helpers: (position of the property name or None, position of the tooltip).
PROPERTY_HELPERS = {"_length": (0, 1), "_center": (None, 0), "_axis": (None, 0)}
PROPERTY_HELPER_NAMES = {"_center": "Center", "_axis": "Axis"}


def display_name(name):
    """How FreeCAD 0.20's property editor shows a property or group name before translating it
    (PropertyItem::setPropertyName): a space before a capital that follows a non-capital."""
    display, upper = "", False
    for c in name:
        if c.isupper() and display and not upper and not display[-1].isspace():
            display += " "
        upper = c.isupper()
        display += c
    return display


def _string(node):
    return node.value if isinstance(node, ast.Constant) and isinstance(node.value, str) else None


def _strings(node):
    """The string literals of a literal (a string, or a tuple or list of them)."""
    if _string(node) is not None:
        return [node.value]
    if isinstance(node, (ast.Tuple, ast.List)):
        return [s for element in node.elts for s in _strings(element)]
    return []


def _name(func):
    return func.id if isinstance(func, ast.Name) else func.attr if isinstance(func, ast.Attribute) else None


def command_context(kind):
    return "RatBez_" + "".join(part.capitalize() for part in kind.split("_"))


class Finder(ast.NodeVisitor):
    def __init__(self, filename):
        self.filename = filename
        self.found = []  # (context, source, filename), in order

    def add(self, context, text):
        if text:
            self.found.append((context, text, self.filename))

    def visit_Call(self, node):
        name = _name(node.func)
        args = node.args
        if name == "translate" and args and isinstance(args[0], ast.IfExp):
            for branch in (args[0].body, args[0].orelse):  # translate("Select..." if picking else "Use selection")
                self.add(CONTEXT, _string(branch))
        if name == "translate" and args and _string(args[0]) is not None:
            context = _string(args[1]) if len(args) > 1 else None
            for keyword in node.keywords:
                if keyword.arg == "context":
                    context = _string(keyword.value)
            self.add(context or CONTEXT, args[0].value)
        elif name == "QT_TRANSLATE_NOOP" and len(args) == 2 and _string(args[0]) and _string(args[1]) is not None:
            self.add(args[0].value, args[1].value)
        elif name == "_tip" and args and _string(args[0]) is not None:
            self.add(PROPERTY, args[0].value)
        elif name in LABEL_ARGUMENTS:
            for position in LABEL_ARGUMENTS[name]:
                if position < len(args):
                    for text in _strings(args[position]):
                        self.add(CONTEXT, text)
        elif name in PROPERTY_HELPERS:
            name_at, tip_at = PROPERTY_HELPERS[name]
            prop = _string(args[name_at]) if name_at is not None and name_at < len(args) else PROPERTY_HELPER_NAMES[name]
            if prop:
                self.add(PROPERTY, display_name(prop))
            if tip_at < len(args) and _string(args[tip_at]) is not None:
                self.add(PROPERTY, args[tip_at].value)
        self.generic_visit(node)

    def visit_ClassDef(self, node):
        values = {}
        for statement in node.body:
            if isinstance(statement, ast.Assign):
                for target in statement.targets:
                    for name, value in self._assigned(target, statement.value):
                        values[name] = value
        kind = _string(values.get("kind")) if values.get("kind") is not None else None
        for attribute in ("menu", "tooltip"):
            text = _string(values[attribute]) if attribute in values else None
            if kind and text:
                self.add(command_context(kind), text)
                self.add(CONTEXT, text)
        for attribute in ("TITLE", "DIMENSIONS"):
            if attribute in values:
                for text in _strings(values[attribute]):
                    self.add(CONTEXT, text)
        for attribute in ("PROPERTIES", "KERNEL_PROPERTIES"):
            if attribute in values and isinstance(values[attribute], ast.Tuple):
                for entry in values[attribute].elts:
                    if isinstance(entry, ast.Tuple) and len(entry.elts) > 1 and _string(entry.elts[1]):
                        self.add(PROPERTY, display_name(entry.elts[1].value))
        self.generic_visit(node)

    @staticmethod
    def _assigned(target, value):
        """(name, value node) pairs of `A = x` and `A, B = x, y`."""
        if isinstance(target, ast.Name):
            return [(target.id, value)]
        if isinstance(target, ast.Tuple) and isinstance(value, ast.Tuple) and len(target.elts) == len(value.elts):
            return [(t.id, v) for t, v in zip(target.elts, value.elts) if isinstance(t, ast.Name)]
        return []

    def visit_Assign(self, node):
        # A property shared by several features: _ALIGN = ("App::PropertyBool", "Align", _tip(...), True): its
        # display name (the tooltip is a _tip call, found by visit_Call).
        value = node.value
        if (isinstance(value, ast.Tuple) and len(value.elts) > 1 and (_string(value.elts[0]) or "").startswith(PROPERTY)
                and _string(value.elts[1])):
            self.add(PROPERTY, display_name(value.elts[1].value))
        # Mode tables: _AXIS_MODES = [("Vertical", "Vertical axis of the profile"), ...]: the second elements.
        for target in node.targets:
            if isinstance(target, ast.Name) and target.id.endswith("_MODES") and isinstance(node.value, ast.List):
                for entry in node.value.elts:
                    if isinstance(entry, ast.Tuple) and len(entry.elts) == 2 and _string(entry.elts[1]):
                        self.add(CONTEXT, entry.elts[1].value)
        self.generic_visit(node)

    def visit_For(self, node):
        # for text, tip, action in (("Add selection", "Append ...", f), ...): translate(text), translate(tip)
        self._literal_loop(node.target, node.iter, node.body)
        self.generic_visit(node)

    def visit_ListComp(self, node):
        # [LinkRow(self, prop, label, ...) for prop, label in (("Profile1", "First profile"), ...)]
        for generator in node.generators:
            self._literal_loop(generator.target, generator.iter, [node.elt])
        self.generic_visit(node)

    def _literal_loop(self, target, iterable, body):
        """The literal elements a loop over a literal tuple hands to translate() or a label argument."""
        targets = ([t.id for t in target.elts if isinstance(t, ast.Name)] if isinstance(target, ast.Tuple)
                   else [target.id] if isinstance(target, ast.Name) else [])
        translated = set()
        for statement in body:
            for n in ast.walk(statement):
                if not isinstance(n, ast.Call):
                    continue
                positions = [0] if _name(n.func) == "translate" else LABEL_ARGUMENTS.get(_name(n.func), [])
                translated.update(n.args[p].id for p in positions if p < len(n.args) and isinstance(n.args[p], ast.Name))
        if not isinstance(iterable, (ast.Tuple, ast.List)):
            return
        for element in iterable.elts:
            values = element.elts if isinstance(element, ast.Tuple) and len(targets) > 1 else [element]
            for name, value in zip(targets, values):
                if name in translated and _string(value) is not None:
                    self.add(CONTEXT, value.value)


def find_strings():
    """{context: {source: [files]}}, contexts and sources in the order found."""
    found = {PROPERTY: {display_name(group): ["ratbez_wb/features.py"] for group in GROUPS}}
    for relative in SOURCES:
        with open(os.path.join(MOD, relative), encoding="utf-8") as handle:
            tree = ast.parse(handle.read(), relative)
        finder = Finder(relative)
        finder.visit(tree)
        for context, text, filename in finder.found:
            files = found.setdefault(context, {}).setdefault(text, [])
            if filename not in files:
                files.append(filename)
    return found


def read_ts(path):
    """{(context, source): translation} of the finished translations of a .ts file, and its language."""
    root = ElementTree.parse(path).getroot()
    translations = {}
    for context in root.iter("context"):
        name = context.findtext("name")
        for message in context.iter("message"):
            translation = message.find("translation")
            if translation is not None and translation.get("type") not in ("unfinished", "obsolete", "vanished") \
                    and translation.text:
                translations[(name, message.findtext("source"))] = translation.text
    return translations, root.get("language")


def _escape(text):
    return (text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
            .replace("'", "&apos;"))


def ts_text(found, language=None, translations=None):
    """The .ts file of the strings found: a template (no language: every translation unfinished) or a
    language's, with its translations where it has them. The sources are ordered by context and text."""
    lines = ['<?xml version="1.0" encoding="utf-8"?>', "<!DOCTYPE TS>",
             '<TS version="2.1"{} sourcelanguage="en">'.format(' language="{}"'.format(language) if language else "")]
    for context in sorted(found):
        lines += ["<context>", "    <name>{}</name>".format(_escape(context))]
        for text in sorted(found[context]):
            lines.append("    <message>")
            for filename in found[context][text]:
                lines.append('        <location filename="../../{}"/>'.format(filename))
            lines.append("        <source>{}</source>".format(_escape(text)))
            translation = (translations or {}).get((context, text))
            if translation:
                lines.append("        <translation>{}</translation>".format(_escape(translation)))
            else:
                lines.append('        <translation type="unfinished"></translation>')
            lines.append("    </message>")
        lines.append("</context>")
    lines.append("</TS>")
    return "\n".join(lines) + "\n"


def language_files():
    return sorted(os.path.join(TRANSLATIONS, name) for name in os.listdir(TRANSLATIONS)
                  if name.startswith("RatBez_") and name.endswith(".ts"))


def lrelease():
    for candidate in ("lrelease", "/usr/lib/qt5/bin/lrelease", "lrelease-qt5"):
        path = shutil.which(candidate) or (candidate if os.path.isfile(candidate) else None)
        if path:
            return path
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="write nothing; exit 1 when a file is stale")
    args = parser.parse_args()
    found = find_strings()
    wanted = {TEMPLATE: ts_text(found)}
    for path in language_files():
        translations, language = read_ts(path)
        wanted[path] = ts_text(found, language, translations)
    stale = []
    for path, text in wanted.items():
        current = open(path, encoding="utf-8").read() if os.path.exists(path) else None
        if current != text:
            stale.append(path)
            if not args.check:
                with open(path, "w", encoding="utf-8") as handle:
                    handle.write(text)
    if args.check:
        for path in stale:
            print("stale: {} (run /usr/bin/python3 freecad_workbench/update_translations.py)".format(
                os.path.relpath(path, HERE)))
        return 1 if stale else 0
    tool = lrelease()
    if tool is None:
        print("lrelease not found (Debian: qttools5-dev-tools): the .qm files were not compiled")
        return 1
    for path in language_files():
        subprocess.run([tool, "-silent", "-removeidentical", path, "-qm", path[:-3] + ".qm"], check=True)
    count = sum(len(sources) for sources in found.values())
    print("{} strings in {} contexts; updated: {}".format(
        count, len(found), ", ".join(os.path.basename(p) for p in stale) or "nothing"))
    return 0


if __name__ == "__main__":
    sys.exit(main())
