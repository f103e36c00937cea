/**
 * Default settings the BoolSurf plugin adds when it loads (in the GUI, pvpython and pvbatch):
 * color maps for BoolSurf's arrays, below the user's and the site's own settings.
 */
#ifndef BoolSurfPluginSettings_h
#define BoolSurfPluginSettings_h

/// Registers the defaults: `ArrangementCell` (the active scalars of region outputs) with the
/// Turbo preset, which has no white that would read as "not selected" on a light surface;
/// `ShapeLabel` (the Label filter's chosen shape) as categories -3..3 with distinct colors,
/// 0 (outside) gray.
void BoolSurfAddDefaultSettings();

#endif
