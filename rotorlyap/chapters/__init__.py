"""The report's chapters: one module per chapter of the book, named for its subject.

Each chapter's module holds that chapter's experiments (the data objects the notebook computes,
with ``facts()``: the numbers the text quotes, rounded to the digits they determine;
``summary()``: the text the chapter prints, which nbval compares; and their CSV export), one
drawing function per figure, and its printed text. A chapter's module imports no other
chapter's module (``tests/test_layers.py``); what two chapters share lives in a small shared
module. Each chapter names its module under its title; the API reference lists them all, the
chapters' and the shared ones. The notebooks' file names (``09_your_own_blade``, ``10_proofs``,
``11_large_disturbances``) keep the order in which the chapters were written, not the book's
numbers (11, 9 and 10).
"""
