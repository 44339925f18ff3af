# RatBez workbench, GUI part. Names defined at the top of this file are not visible inside the
# workbench's methods under FreeCAD 0.20, so everything they need is imported inside them.

import FreeCADGui


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
