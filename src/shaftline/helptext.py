"""Help texts that a capability declares with its verbs (:attr:`~shaftline.registry.Verb.strict`).

Kept apart from :mod:`shaftline.commandline`, which imports typer and rich: a capability
module builds its verbs' help from here, so that importing it for the case schema, the
registry or a notebook imports no command-line library.
"""

from __future__ import annotations


def strict_help(criteria: str, always: str = "") -> str:
    """The ``--strict`` help of a verb, from what its capability's findings judge
    (:class:`~shaftline.registry.Finding`): ``criteria``, the design criteria (``criterion=True``:
    exit status 3 only with ``--strict``); ``always``, what exits with 3 without it
    (``criterion=False``), empty when nothing of the verb does.

    Examples
    --------
    >>> strict_help("a rule check fails")
    'Exit with status 3 also when a rule check fails. Without it, no result of this command exits with 3.'
    """
    text = f"Exit with status 3 also when {criteria}."
    if always:
        return f"{text} Without it, status 3 only for {always}."
    return f"{text} Without it, no result of this command exits with 3."
