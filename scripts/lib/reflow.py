"""Markdown rewrapping for the result generators: a generated page's prose is assembled from
fragments and figures of the run, so its paragraphs and list items are rewrapped once, when the
page is complete; tables, headings, images, code and indented blocks are kept as they are."""
import textwrap


def reflow(text, width=100):
    """Paragraphs and list items rewrapped to `width`; tables, headings, images and code kept."""
    def fill(s, first="", rest=""):
        return textwrap.fill(s, width, initial_indent=first, subsequent_indent=rest,
                             break_long_words=False, break_on_hyphens=False)
    out = []
    for block in text.split("\n\n"):
        lines = block.split("\n")
        if not block.strip() or any(l.startswith(("|", "#", "!", "```", "    ")) for l in lines):
            out.append(block)
        elif lines[0].startswith("- "):
            items = []
            for l in lines:
                if l.startswith("- "):
                    items.append([])
                items[-1].append(l.strip())
            out.append("\n".join(fill(" ".join(i)[2:], "- ", "  ") for i in items))
        else:
            out.append(fill(" ".join(l.strip() for l in lines)))
    return "\n\n".join(out)
