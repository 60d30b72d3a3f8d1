"""The ``motionvar`` command: generate BVH motion from the models a pipeline run saved
under ``results/<dataset>/models/`` (one subcommand per paper, plus ``models``, which lists
what is fitted). Glue only: each subcommand parses its arguments, loads model files with
the papers' loaders, calls the paper's ``generate`` module and writes BVH
(:func:`motionvar.io.bvh.write_bvh`). Nothing in the library imports this package."""
