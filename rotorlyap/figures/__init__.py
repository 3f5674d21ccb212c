"""Figures of the report: one data function and one drawing function per figure.

``theory``: the theorem and algorithm chapters (small periodic systems).
"""
