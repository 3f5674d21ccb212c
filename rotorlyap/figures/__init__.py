"""Figures of the report, one module per part of the book.

Each module holds, for its chapters, the data objects the notebooks compute (with ``facts()``:
the numbers the text quotes, rounded to the digits they determine; ``summary()``: the text the
chapter prints, which nbval compares; and their CSV export) and one drawing function per
figure.

* :mod:`~rotorlyap.figures.theory`: chapters 1 and 2, the theorem and the algorithm (small
  periodic systems);
* :mod:`~rotorlyap.figures.blade_model`: chapters 3 and 4, the blade and Table I;
* :mod:`~rotorlyap.figures.paper`: chapters 5 and 6, the paper's Figs 4-8;
* :mod:`~rotorlyap.figures.validation`: chapter 7, beyond the paper;
* :mod:`~rotorlyap.figures.flight`: chapter 8, the forward flight of a trimmed helicopter;
* :mod:`~rotorlyap.figures.proofs`: chapter 9, certificates as proofs;
* :mod:`~rotorlyap.figures.large_disturbances`: chapter 10, how large a disturbance;
* :mod:`~rotorlyap.figures.your_blade`: chapter 11, your own blade;
* :mod:`~rotorlyap.figures.style` (shared colours), :mod:`~rotorlyap.figures.export` (CSV,
  glue, tables), :mod:`~rotorlyap.figures.commands` and
  :mod:`~rotorlyap.figures.blade_commands` (the command line's figures).

The chapter numbers are the book's; the notebooks' file names (``09_your_own_blade``,
``10_proofs``, ``11_large_disturbances``) keep the order in which the chapters were written.
"""
