"""Figures of the report, one module per part of the book.

Each module holds, for its chapters, the data objects the notebooks compute (with ``facts()``:
the numbers the text quotes, rounded to the digits they determine; ``summary()``: the text the
chapter prints, which nbval compares; and their CSV export) and one drawing function per
figure.

* :mod:`~rotorlyap.chapters.theory`: chapters 1 and 2, the theorem and the algorithm (small
  periodic systems);
* :mod:`~rotorlyap.chapters.blade_model`: chapters 3 and 4, the blade and Table I;
* :mod:`~rotorlyap.chapters.paper`: chapters 5 and 6, the paper's Figs 4-8;
* :mod:`~rotorlyap.chapters.validation`: chapter 7, beyond the paper;
* :mod:`~rotorlyap.chapters.flight`: chapter 8, the forward flight of a trimmed helicopter;
* :mod:`~rotorlyap.chapters.proofs`: chapter 9, certificates as proofs;
* :mod:`~rotorlyap.chapters.large_disturbances`: chapter 10, how large a disturbance;
* :mod:`~rotorlyap.chapters.your_blade`: chapter 11, your own blade;
* :mod:`~rotorlyap.chapters.style` (shared colours), :mod:`~rotorlyap.chapters.export` (CSV,
  glue, tables), :mod:`~rotorlyap.chapters.commands` and
  :mod:`~rotorlyap.chapters.blade_commands` (the command line's figures).

The chapter numbers are the book's; the notebooks' file names (``09_your_own_blade``,
``10_proofs``, ``11_large_disturbances``) keep the order in which the chapters were written.
"""
