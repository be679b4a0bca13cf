"""The pytest suite of the wdm_crust Python package (a package, so that its shared modules
cannot collide with other test folders' in one pytest run)."""
