"""The pipeline's fork server imports this first (pipeline._pool_context): the server then dies with the process that
started it, as each worker it forks dies with the server, so that a kill -9 of a run leaves no process behind (a
worker holds the server open, and the server would otherwise wait on it for ever)."""

from dynclevr.pipeline import die_with_parent

die_with_parent()
