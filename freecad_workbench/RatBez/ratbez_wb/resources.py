"""Paths of the workbench's resources (icons)."""

import os

_HERE = os.path.dirname(os.path.abspath(__file__))
ICON_DIR = os.path.join(os.path.dirname(_HERE), "Resources", "icons")


def icon(name):
    """Absolute path of Resources/icons/<name>.svg."""
    return os.path.join(ICON_DIR, name + ".svg")
