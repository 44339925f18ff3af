"""Translatable strings: translate() at run time, QT_TRANSLATE_NOOP() where FreeCAD translates later
(command resources, property tooltips). Contexts: "RatBez" for the workbench's own texts and the
command name (RatBez_Cylinder, ...) for a command's menu text and tooltip, as FreeCAD's own modules do.
Falls back to the text itself where FreeCAD.Qt is missing."""

import FreeCAD as App

CONTEXT = "RatBez"

try:
    _qt = App.Qt
    _translate = _qt.translate
    QT_TRANSLATE_NOOP = _qt.QT_TRANSLATE_NOOP
except AttributeError:  # pragma: no cover - FreeCAD without FreeCAD.Qt
    def _translate(context, text):
        return text

    def QT_TRANSLATE_NOOP(context, text):
        return text


def translate(text, context=CONTEXT):
    return _translate(context, text)
