"""Cached generated code (see rotorlyap.model.derivation)."""
