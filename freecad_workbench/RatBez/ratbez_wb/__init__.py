"""Implementation of the RatBez FreeCAD workbench.

One concept per module:
  kernel          -- importing the compiled ratbez module, with a clear message when it is missing
  conversion      -- FreeCAD edges / wires / sketches -> ratbez curves, ratbez solids -> Part shapes
  features        -- the Part::FeaturePython proxies (properties and execute)
  view_providers  -- their view providers (icons, tree children)
  commands        -- the GUI commands RatBez_*
  dialogs         -- Qt dialogs used by the commands
  resources       -- paths of the icons
"""
