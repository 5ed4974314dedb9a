"""One module per stage, each declaring `STAGE` (what it reads, writes, its version and params) and `run_scene`."""
