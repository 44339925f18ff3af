"""Implementation of the RatBez FreeCAD workbench.

One concept per module:
  kernel           -- importing the compiled ratbez module; reading its errors (argument, reason)
  errors           -- failed recomputes in the property editor's words, reported once
  conversion       -- FreeCAD profiles -> ratbez curves (loops, holes, axes, normals); solids -> Part shapes
  features         -- the Part::FeaturePython proxies (properties and execute)
  view_providers   -- their view providers (icons, tree children, task panel on double-click)
  task_panels      -- the task panels (live preview, OK / Cancel as one undo step)
  commands         -- the GUI commands RatBez_*
  dialogs          -- the OpenSCAD export dialog
  preferences      -- the user preferences; preferences_page -- their page in Edit > Preferences
  i18n             -- translate() / QT_TRANSLATE_NOOP
  text             -- one-line text for messages and files
  resources        -- paths of the icons
"""
