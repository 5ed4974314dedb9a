"""The vehicle catalogue: 5 categories, 21 sub-types, procedural part meshes, physical properties."""

from dynclevr.assets.catalogue import CATEGORIES, SUBTYPES, Asset, get_asset

__all__ = ["CATEGORIES", "SUBTYPES", "Asset", "get_asset"]
