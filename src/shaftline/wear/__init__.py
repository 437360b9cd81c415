"""Wear of bearings in service: Archard's law, sliding distance from pitch logs, Weibull life."""
