"""``python -m lod2energy.cfd``: the CFD case's command (the case itself is :mod:`lod2energy.exporters.cfd`)."""
