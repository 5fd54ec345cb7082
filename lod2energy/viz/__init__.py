"""Pictures of what lod2energy did: the self-contained ``report.html`` and ``lod2energy view``.

:func:`write_report_html` writes the page for a report of ``export``, ``repair --report`` or
``validate --report``; :func:`lod2energy.viz.view.view` writes (and opens) the panel of one building of a file.
"""
from lod2energy.viz.report import (  # noqa: F401
    DEFAULT_CAP, keep, render_report_html, write_report_html,
)

__all__ = ["DEFAULT_CAP", "keep", "render_report_html", "write_report_html"]
