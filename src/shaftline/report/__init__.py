"""The report layer: section content as data (:mod:`.blocks`), the HTML report
(:mod:`.html`), the terminal view (:mod:`.terminal`) and the axes helper figure functions
use (:mod:`.plotting`). It alone decides how figures are written to files."""
