"""Sphinx extension: an author-year bibliography list to match the author-year citations.

sphinxcontrib-bibtex writes citations in the text as "[Deepak and Ananthasuresh, 2012a]"
(``bibtex_reference_style: author_year``) but labels the list with the formatting style's
labels, numbers for pybtex's ``plain``. This extension registers the pybtex formatting style
``authoryear``: pybtex's ``plain`` entries, sorted by author, year and title, each labelled
with the same author-year text the citations show (one author: "LaCoste, 1934"; two: "Singh and
Ananthasuresh, 2013"; more: "Lustig et al., 2015"; no year: "n.d."). Two works of the same
authors and year carry their letter in the ``year`` field of ``book/references.bib`` (2012a,
2012b), so text and list agree without any renumbering here.

Use it with ``bibtex_default_style: authoryear`` and this module among the local extensions.
"""
from __future__ import annotations

from pybtex.plugin import register_plugin
from pybtex.style.formatting.plain import Style as PlainStyle
from pybtex.style.labels import BaseLabelStyle

__all__ = ["AuthorYearLabelStyle", "AuthorYearStyle", "author_year_label", "setup"]


def _last_names(person) -> str:
    """A person's printed surname ("LaCoste", "van der Kooij"), without TeX braces."""
    return " ".join(person.prelast_names + person.last_names).replace("{", "").replace("}", "")


def author_year_label(entry) -> str:
    """The author-year label of one pybtex entry, as the text cites it.

    Parameters
    ----------
    entry : pybtex.database.Entry
        A bibliography entry (authors, else editors, else its title; ``year`` or "n.d.").

    Returns
    -------
    str

    Examples
    --------
    >>> from pybtex.database import Entry, Person
    >>> e = Entry("article", fields={"year": "2012a"},
    ...           persons={"author": [Person("Deepak, S. R."), Person("Ananthasuresh, G. K.")]})
    >>> author_year_label(e)
    'Deepak and Ananthasuresh, 2012a'
    >>> author_year_label(Entry("misc", fields={"title": "Lecture"}, persons={"author": [Person("{Theory of Mechanisms}")]}))
    'Theory of Mechanisms, n.d.'
    """
    persons = entry.persons.get("author") or entry.persons.get("editor") or []
    names = [_last_names(p) for p in persons]
    if not names:
        who = entry.fields.get("title", "Anonymous")
    elif len(names) == 1:
        who = names[0]
    elif len(names) == 2:
        who = f"{names[0]} and {names[1]}"
    else:
        who = f"{names[0]} et al."
    return f"{who}, {entry.fields.get('year', 'n.d.')}"


class AuthorYearLabelStyle(BaseLabelStyle):
    """pybtex label style: "Author, Year" (see :func:`author_year_label`)."""

    def format_labels(self, sorted_entries):
        for entry in sorted_entries:
            yield author_year_label(entry)


class AuthorYearStyle(PlainStyle):
    """pybtex's ``plain`` entries, sorted by author and year, with author-year labels."""

    default_sorting_style = "author_year_title"

    def __init__(self, label_style=None, **kwargs):
        super().__init__(**kwargs)
        self.label_style = AuthorYearLabelStyle()
        self.format_labels = self.label_style.format_labels


def setup(app):
    """Register the pybtex style ``authoryear`` (for ``bibtex_default_style``)."""
    register_plugin("pybtex.style.formatting", "authoryear", AuthorYearStyle)
    return {"version": "1.0", "parallel_read_safe": True, "parallel_write_safe": True}
