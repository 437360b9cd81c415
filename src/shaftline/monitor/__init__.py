"""Film-thickness monitoring from eddy-current probes (seed 001, issue 13).

Modules are named after the physics: :mod:`~shaftline.monitor.probes` (layout,
calibration, checks), :mod:`~shaftline.monitor.identification` (journal-centre orbit,
film and correction factor at the probe sections), :mod:`~shaftline.monitor.bending`
(journal centre line and film along the whole bearing), :mod:`~shaftline.monitor.regimes`
(film-thickness ratio and lubrication regimes), :mod:`~shaftline.monitor.orbits` (orbit
descriptors with a keyphasor), :mod:`~shaftline.monitor.forward` (synthetic probe
signals of the seed's rig from the bearing solver and the shaft model, the validation),
:mod:`~shaftline.monitor.study` (``identify_window``: one block from volts to film, regimes
and descriptors) and :mod:`~shaftline.monitor.figures`; ``case.py`` and ``capability.py``
are the ``[monitor]`` table and the capability (the ``monitor simulate`` verb),
``presentation.py`` and ``trend_report.py`` what a result and the trend database show, and
``commands.py`` the ``monitor identify`` and ``monitor trend`` commands.

Every function takes and returns SI units; sample blocks are (samples x channels)
arrays in the channel order of :attr:`ProbeLayout.channels`, so that a reader can feed
chunks of a long recording.
"""
