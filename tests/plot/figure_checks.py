"""Checks on drawn figures shared by the plot tests."""

from matplotlib.backends.backend_agg import FigureCanvasAgg


def texts_outside(fig, texts):
    """``(text, bounds)`` of each of ``texts`` whose drawn extent sticks out of ``fig`` (by > ½ pixel)."""
    FigureCanvasAgg(fig)
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    box = fig.bbox
    out = []
    for text in texts:
        ext = text.get_window_extent(renderer)
        if ext.x0 < box.x0 - 0.5 or ext.x1 > box.x1 + 0.5 or ext.y0 < box.y0 - 0.5 or ext.y1 > box.y1 + 0.5:
            out.append((text.get_text(), ext.bounds))
    return out


def titles_and_labels(fig):
    """Every axes' title and axis labels, and the figure's suptitle if any."""
    texts = [t for ax in fig.axes for t in (ax.title, ax.xaxis.label, ax.yaxis.label) if t.get_text()]
    if fig._suptitle is not None:
        texts.append(fig._suptitle)
    return texts
