"""The report's chapters: one module per chapter of the book, named for its subject.

Each chapter's module holds that chapter's experiments, drawings and printed text, by one
convention:

* a data function per result returns a frozen dataclass (arrays, no plotting) and takes its
  grids as arguments, so that the notebook, a benchmark or a test chooses the resolution;
* the data object has ``summary()``, the text the chapter prints, rounded to the digits the
  computation determines (what nbval compares, since images are not), and ``facts()``,
  ``{glue name: value}``, the numbers the chapter's text quotes, rounded the same way (glued
  with :func:`rotorlyap.chapters.export.glue_facts`); a table has ``markdown()``, and
  ``export()`` gives a figure's CSV where the dataclass itself is not
  (:func:`rotorlyap.chapters.export.figure_csv`);
* ``plot_*`` draws the data on matplotlib ``Axes``; ``figure_*`` creates, draws, lays out and
  returns the whole figure, closed in pyplot so that a notebook shows it only where it is glued.

A chapter's cell is then one call per step::

    region = algorithm.start_region_data(res)
    glue("fig_start_region", algorithm.figure_start_region(region), display=False)
    figure_csv(region, "_data/fig-start-region.csv")
    print(region.summary())
    glue_facts(region.facts())

Azimuths are in radians unless a name ends in ``_deg``; ``psi = 0`` has the blade over the
tail and ``psi = 90 deg`` is the advancing side; growth rates are per rev (per radian of
``psi``). A chapter's module imports no other
chapter's module (``tests/test_layers.py``); what two chapters share lives in a small shared
module. Each chapter names its module under its title; the API reference lists them all, the
chapters' and the shared ones. The notebooks' file names (``09_your_own_blade``, ``10_proofs``,
``11_large_disturbances``) keep the order in which the chapters were written, not the book's
numbers (11, 9 and 10).
"""
