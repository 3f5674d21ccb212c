"""The shared notebook execution (``book/_ext/notebook_execution.py``): a notebook the test run
executed is found by the build's cache lookup, and no output survives an edit of the package.

These tests build a throw-away project in a temporary folder; they execute no notebook.
"""

from __future__ import annotations

import sys
from pathlib import Path

import nbformat
import pytest

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "book" / "_ext"))
import notebook_execution as ne  # noqa: E402


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "rotorlyap" / "sub").mkdir(parents=True)
    (tmp_path / "rotorlyap" / "__init__.py").write_text("A = 1\n")
    (tmp_path / "rotorlyap" / "sub" / "model.py").write_text("B = 2\n")
    (tmp_path / "requirements.txt").write_text("numpy==2.4.6\n")
    (tmp_path / "pyproject.toml").write_text("[project]\nname = 'x'\n")
    return tmp_path


def _executed_notebook(code: str, printed: str) -> nbformat.NotebookNode:
    nb = nbformat.v4.new_notebook(metadata={"kernelspec": {"name": "python3", "display_name": "Python 3",
                                                           "language": "python"}})
    cell = nbformat.v4.new_code_cell(code, execution_count=1)
    cell.outputs = [nbformat.v4.new_output("stream", name="stdout", text=printed)]
    nb.cells = [nbformat.v4.new_markdown_cell("# A chapter"), cell]
    return nb


def test_fingerprint_changes_with_any_package_file_or_requirement_and_nothing_else(project):
    first = ne.fingerprint(project)
    assert ne.fingerprint(project) == first  # deterministic
    (project / "notes.md").write_text("prose\n")  # not something outputs depend on
    assert ne.fingerprint(project) == first
    for path, text in ((project / "rotorlyap" / "sub" / "model.py", "B = 3\n"),
                       (project / "requirements.txt", "numpy==2.4.7\n"),
                       (project / "rotorlyap" / "new.py", "")):
        before = ne.fingerprint(project)
        path.write_text(text)
        assert ne.fingerprint(project) != before, path.name


def test_a_stored_notebook_is_matched_by_its_code_as_the_build_looks_it_up(project):
    from jupyter_cache import get_cache

    cache_dir = project / "_build" / ".jupyter_cache"
    executed = _executed_notebook("print(6 * 7)", "42\n")
    assert ne.store([(project / "book" / "ch.ipynb", executed, 1.0)], cache_dir, project) == ["ch.ipynb"]
    # the build reads the source notebook: same code, other prose, no outputs
    source = _executed_notebook("print(6 * 7)", "")
    source.cells[0].source = "# The chapter, reworded"
    source.cells[1].outputs, source.cells[1].execution_count = [], None
    _, merged = get_cache(str(cache_dir)).merge_match_into_notebook(source)
    assert merged.cells[0].source == "# The chapter, reworded"
    assert merged.cells[1].outputs[0]["text"] == "42\n"
    # other code: no match, the build executes it
    with pytest.raises(KeyError):
        get_cache(str(cache_dir)).match_cache_notebook(_executed_notebook("print(6 * 8)", ""))


def test_an_edit_of_the_package_empties_the_cache_and_a_current_one_is_kept(project):
    from jupyter_cache import get_cache

    cache_dir = project / "_build" / ".jupyter_cache"
    ne.store([(project / "ch.ipynb", _executed_notebook("print(1)", "1\n"), 1.0)], cache_dir, project)
    assert ne.refresh(cache_dir, project) is False  # unchanged tree: kept
    assert len(get_cache(str(cache_dir)).list_cache_records()) == 1
    (project / "rotorlyap" / "__init__.py").write_text("A = 2\n")
    assert ne.refresh(cache_dir, project) is True  # stale: emptied
    assert get_cache(str(cache_dir)).list_cache_records() == []
    assert ne.refresh(cache_dir, project) is False  # and stamped with the new tree
    assert ne.refresh(cache_dir, project, force_clear=True) is True


def test_glued_figures_of_every_kind_are_skipped_by_the_comparison():
    for mime in ("image/png", "application/papermill.record/image/png", "image/svg+xml"):
        assert mime in ne.IMAGE_MIMES
    assert not any(m.startswith("text/") or "/text/" in m for m in ne.IMAGE_MIMES)


def test_outputs_of_a_run_during_which_the_package_changed_are_emptied_by_the_next_build(project):
    from jupyter_cache import get_cache

    cache_dir = project / "_build" / ".jupyter_cache"
    at_start = ne.fingerprint(project)
    (project / "rotorlyap" / "__init__.py").write_text("A = 3\n")  # edited while the tests ran
    ne.store([(project / "ch.ipynb", _executed_notebook("print(1)", "1\n"), 1.0)], cache_dir, project,
             executed_with=at_start)
    assert len(get_cache(str(cache_dir)).list_cache_records()) == 1
    assert ne.refresh(cache_dir, project) is True  # what the build does first
    assert get_cache(str(cache_dir)).list_cache_records() == []
