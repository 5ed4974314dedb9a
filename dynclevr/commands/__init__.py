"""Commands beyond the stages. Each module here defines `register(app)` and imports heavy libraries lazily."""
