"""Text that goes into one line of something we write: a report-view message, a comment in a file."""


def one_line(text):
    """`text` with every control character (newline, tab, escape, the Unicode line and paragraph
    separators ...) shown as a \\uXXXX escape: a crafted Label cannot end a comment line in an exported
    file and become code there, nor forge extra lines in the report view."""
    return "".join(c if c.isprintable() else "\\u{:04x}".format(ord(c)) for c in str(text))
