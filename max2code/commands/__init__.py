"""The subcommands (cli.py dispatches `max2code NAME` to NAME's main), the options
they share, and the independent oracle that check and vectors compare against (kept
apart from codegen/ on purpose). Nothing below this package imports it."""
