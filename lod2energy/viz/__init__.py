"""Pictures of what lod2energy did: the self-contained ``report.html`` and ``lod2energy view``.

:func:`write_report_html` writes the page for a report of ``export``, ``repair --report`` or
``validate --report``; :func:`view` writes (and opens) the panel of one building of a file.
"""
from lod2energy.viz.report import (  # noqa: F401
    DEFAULT_CAP, keep, render_report_html, write_report_html,
)

_VIEW = ("cmd_view", "write_report_for", "prepare_outputs")


def __getattr__(name):
    # the view functions prepare buildings through lod2energy.pipeline, which writes report.html
    # through this package: they load on first use, so the pipeline never imports itself
    if name in _VIEW:
        from importlib import import_module
        return getattr(import_module("lod2energy.viz.view"), name)
    raise AttributeError(f"module 'lod2energy.viz' has no attribute {name!r}")

__all__ = ["DEFAULT_CAP", "keep", "render_report_html", "write_report_html", "write_report_for",
           "cmd_view"]
