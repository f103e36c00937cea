/**
 * Default settings the BoolSurf plugin adds when it loads (in the GUI, pvpython and pvbatch):
 * color maps for BoolSurf's arrays, below the user's and the site's own settings.
 */
#ifndef BoolSurfPluginSettings_h
#define BoolSurfPluginSettings_h

/// Registers the defaults: `Region` (the active scalars of region outputs, 1 everywhere) as
/// one category in orange, so a result shows as one region distinct from a light surface;
/// `ArrangementCell` (per-cell coloring) as 12 bright steps, with no near-white that would
/// read as "not selected" and no near-black that would read as a hole; `ShapeLabel` (the
/// Label filter's chosen shape) as categories -3..3 with distinct colors, 0 (outside) gray.
void BoolSurfAddDefaultSettings();

#endif
