"""Cached generated code (see rotorlyap.derivation)."""
