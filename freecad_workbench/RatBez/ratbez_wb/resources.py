"""Paths of the workbench's resources (icons, translations)."""

import os

_HERE = os.path.dirname(os.path.abspath(__file__))
ICON_DIR = os.path.join(os.path.dirname(_HERE), "Resources", "icons")
# RatBez_<language>.qm, loaded by FreeCAD for its current language (FreeCADGui.addLanguagePath).
TRANSLATIONS_DIR = os.path.join(os.path.dirname(_HERE), "Resources", "translations")


def icon(name):
    """Absolute path of Resources/icons/<name>.svg."""
    return os.path.join(ICON_DIR, name + ".svg")
