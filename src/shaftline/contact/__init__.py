"""Lubricated non-conformal contacts (issue 14, part A): Hertz contact, EHL film, lubricant
rheology and mixed friction after seed 002 (Ciulli et al. 2010).

Every function takes numpy arrays that broadcast against each other, so that a gear mesh can
evaluate a whole path of contact (and a map of load stages x speeds) in one call:
:func:`shaftline.contact.lubricated.evaluate` chains them.

Modules: :mod:`~shaftline.contact.hertz` (dry elastic contact), :mod:`~shaftline.contact.ehl`
(film thickness, regimes, thermal reduction, Lambda), :mod:`~shaftline.contact.rheology`
(viscosity against pressure and temperature, limiting shear stress, lubricant data),
:mod:`~shaftline.contact.friction` (seed 002 Eq. 1-6) and the capability's layer
(``case.py``, ``study.py``, ``figures.py``, ``capability.py``).
"""
