"""The claims summary, the per-seed stability table, the results page and the ``report``
config section's settings."""
