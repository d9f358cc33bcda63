"""Task failures the client reports as one line: bad input (exit 2) or a failed run (exit 1)."""


class VctInputError(Exception):
    """vct exited 2: the line it printed names the file and what is wrong."""


class VctTaskError(Exception):
    """vct failed otherwise (exit 1, a signal): the last line of its stderr."""
