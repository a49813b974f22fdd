"""The case a chart shows, as a footer line on every figure a plot script saves.

`gearstiff` passes the case (the pair, its torque, the speed: CommandContext::chart_case) in the
environment variable GEARSTIFF_CHART_CASE when it runs a plot script. Importing this module makes
every `Figure.savefig` write that line at the bottom left of the figure, so a chart copied into a
slide or a report still says which gears and which load it belongs to. Without the variable (a
script run by hand) nothing changes.
"""
import os

import matplotlib.figure

CASE = os.environ.get("GEARSTIFF_CHART_CASE", "").strip()

if CASE:
    _savefig = matplotlib.figure.Figure.savefig

    def _savefig_with_case(fig, *args, **kwargs):
        # Once per figure: a script that saves a figure twice gets one footer.
        # Below the figure's own bottom edge, and the saved area grown to hold it ("tight"):
        # inside the figure it would cover an x label wherever the axes reach the bottom.
        if not getattr(fig, "_gearstiff_case", False):
            fig.text(0.005, 0.0, "gearstiff: " + CASE, fontsize=7, color="0.35",
                     ha="left", va="top")
            fig._gearstiff_case = True
        kwargs.setdefault("bbox_inches", "tight")
        return _savefig(fig, *args, **kwargs)

    matplotlib.figure.Figure.savefig = _savefig_with_case
