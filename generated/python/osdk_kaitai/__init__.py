"""Parsers generated from spec/*.ksy by tools/regen.py. Do not edit."""
