"""The Python examples of the docs run as shown: every `>>>` line of docs/python.md and docs/formulas.md is
run and what it prints is compared with what the page shows (doctest), so a page
cannot show a value the module does not return."""

import doctest
import os
import unittest

from viscor_test_support import SOURCE_DIR


def markdown_doctest(page):
    """The page's `>>>` examples as one doctest; a code fence ends an example's output."""
    with open(page, encoding="utf-8") as f:
        text = "".join("\n" if line.startswith("```") else line for line in f)
    return doctest.DocTestParser().get_doctest(text, {}, os.path.basename(page), page, 0)


class DocsShowWhatTheModuleReturns(unittest.TestCase):
    def check_page(self, name, at_least):
        test = markdown_doctest(os.path.join(SOURCE_DIR, "docs", name))
        runner = doctest.DocTestRunner(optionflags=doctest.ELLIPSIS)
        runner.run(test)
        result = runner.summarize(verbose=False)
        self.assertGreaterEqual(result.attempted, at_least, f"docs/{name} lost its >>> examples")
        self.assertEqual(result.failed, 0, f"docs/{name} shows values the module does not return (see above)")

    def test_python_md(self):
        self.check_page("python.md", 15)

    def test_formulas_md(self):
        self.check_page("formulas.md", 12)

    def test_a_wrong_value_on_the_page_fails(self):
        text = ">>> 1 + 1\n3\n"
        test = doctest.DocTestParser().get_doctest(text, {}, "wrong", "wrong", 0)
        runner = doctest.DocTestRunner()
        runner.run(test, out=lambda _: None)
        self.assertEqual(runner.summarize(verbose=False).failed, 1)


if __name__ == "__main__":
    unittest.main()
