"""The report's chapters: one module per chapter of the book, named for its subject.

Each chapter's module holds that chapter's experiments (the data objects the notebook computes,
with ``facts()``: the numbers the text quotes, rounded to the digits they determine;
``summary()``: the text the chapter prints, which nbval compares; and their CSV export), one
drawing function per figure, and its printed text. A chapter's module imports no other
chapter's module (``tests/test_layers.py``); what two chapters share lives in a small shared
module. Each chapter names its module under its title.

Chapters (the book's numbers):

* :mod:`~rotorlyap.chapters.technical_stability`: 1, technical stability;
* :mod:`~rotorlyap.chapters.algorithm`: 2, the algorithm (small periodic systems);
* :mod:`~rotorlyap.chapters.blade_model`: 3, the blade model;
* :mod:`~rotorlyap.chapters.table_i`: 4, Table I and the missing data;
* :mod:`~rotorlyap.chapters.hover`: 5, hover (the paper's Figs 4 and 5);
* :mod:`~rotorlyap.chapters.forward_flight`: 6, forward flight (the paper's Figs 6-8);
* :mod:`~rotorlyap.chapters.validation`: 7, validation and beyond;
* :mod:`~rotorlyap.chapters.trimmed_flight`: 8, the forward flight of a trimmed helicopter;
* :mod:`~rotorlyap.chapters.proofs`: 9, certificates as proofs;
* :mod:`~rotorlyap.chapters.large_disturbances`: 10, how large a disturbance;
* :mod:`~rotorlyap.chapters.your_blade`: 11, your own blade.

Shared: :mod:`~rotorlyap.chapters.norm_history` (chapters 1 and 2),
:mod:`~rotorlyap.chapters.blade_formulas` (3 and 4), :mod:`~rotorlyap.chapters.cases` (5 and
6), :mod:`~rotorlyap.chapters.scans` (7 and 8, and the advance ratios chapter 9 proves),
:mod:`~rotorlyap.chapters.style` (colours and the legibility rule),
:mod:`~rotorlyap.chapters.export` (CSV, glue, tables), :mod:`~rotorlyap.chapters.commands`
and :mod:`~rotorlyap.chapters.blade_commands` (the command line's figures).

The notebooks' file names (``09_your_own_blade``, ``10_proofs``, ``11_large_disturbances``)
keep the order in which the chapters were written.
"""
