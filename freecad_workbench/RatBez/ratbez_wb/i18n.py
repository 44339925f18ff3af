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


_english = None  # the installed QTranslator of RatBez_en.qm (kept alive here)


def install_english():
    """Install RatBez_en.qm below FreeCAD's own translators. FreeCAD 0.20 loads a module's .qm files only
    for a language other than English (and none at all under the C locale), but the English file holds the
    display fixes of English texts: the property editor splits the group name "RatBez" at its capitals
    and translates "Rat Bez" (App::Property), which this file turns back into "RatBez". Translators
    installed later (FreeCAD's, for German, ...) take precedence over it."""
    global _english
    if _english is not None:
        return True
    import os
    from PySide import QtCore
    from . import resources
    translator = QtCore.QTranslator()
    if not translator.load(os.path.join(resources.TRANSLATIONS_DIR, "RatBez_en.qm")):
        return False
    QtCore.QCoreApplication.installTranslator(translator)
    _english = translator
    return True
