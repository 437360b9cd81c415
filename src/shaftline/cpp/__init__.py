"""Controllable-pitch-propeller blade bearings: loads, friction torque, fretting, hydraulics."""
