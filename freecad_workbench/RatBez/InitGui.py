# RatBez workbench, GUI part. Names defined at the top of this file are not visible inside the
# workbench's methods under FreeCAD 0.20, so everything they need is imported inside them.

import FreeCADGui


def _setup():
    """Translations and icons, before the workbench's menus and the preferences dialog ask for them: FreeCAD
    loads Resources/translations/RatBez_<language>.qm for its language (the English one makes the property
    group read "RatBez", which the property editor would split to "Rat Bez"), and finds the preferences
    page's icon, preferences-ratbez.svg, among the workbench's icons. The English file is installed by the
    workbench itself (i18n.install_english), since FreeCAD loads none for English."""
    from ratbez_wb import i18n, resources
    i18n.install_english()
    FreeCADGui.addLanguagePath(resources.TRANSLATIONS_DIR)
    FreeCADGui.updateLocale()
    FreeCADGui.addIconPath(resources.ICON_DIR)


_setup()


class RatBezWorkbench(FreeCADGui.Workbench):
    MenuText = "RatBez"
    ToolTip = ("Exact rational Bézier / NURBS solids built by the ratbez kernel, with OpenSCAD "
               "export and OpenCASCADE checks")

    def __init__(self):
        from ratbez_wb import resources
        self.__class__.Icon = resources.icon("RatBezWorkbench")

    def Initialize(self):
        from ratbez_wb import commands, preferences_page
        from ratbez_wb.i18n import QT_TRANSLATE_NOOP
        commands.register()
        self.appendToolbar(QT_TRANSLATE_NOOP("Workbench", "RatBez"), commands.CREATE_COMMAND_NAMES)
        self.appendToolbar(QT_TRANSLATE_NOOP("Workbench", "RatBez tools"), commands.TOOL_COMMAND_NAMES)
        self.appendMenu(QT_TRANSLATE_NOOP("Workbench", "RatBez"),
                        commands.CREATE_COMMAND_NAMES + ["Separator"] + commands.TOOL_COMMAND_NAMES)
        FreeCADGui.addPreferencePage(preferences_page.PreferencesPage, "RatBez")

    def Activated(self):
        pass

    def Deactivated(self):
        pass

    def ContextMenu(self, recipient):
        from ratbez_wb import commands
        if recipient == "Tree":
            self.appendContextMenu("RatBez", commands.TOOL_COMMAND_NAMES)

    def GetClassName(self):
        return "Gui::PythonWorkbench"


FreeCADGui.addWorkbench(RatBezWorkbench())
