"""Gear meshes (issue 14, part B): involute geometry and kinematics of spur and helical pairs
so far (:mod:`shaftline.gears.mesh`); the scuffing criteria follow."""
