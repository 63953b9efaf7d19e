"""The one definition of the project root (moos_lint.files.project)."""

from __future__ import annotations

import os

from moos_lint.files.project import is_within, project_root, real_within


def test_config_folder_wins(tmp_path):
    (tmp_path / "repo" / ".git").mkdir(parents=True)
    cfg = tmp_path / "repo" / "missions" / "moos-lint.toml"
    cfg.parent.mkdir()
    cfg.write_text("")
    assert project_root([cfg.parent / "a.moos"], cfg) == str(cfg.parent)


def test_vcs_top_without_config(tmp_path):
    (tmp_path / "repo" / ".git").mkdir(parents=True)
    deep = tmp_path / "repo" / "missions" / "alpha"
    deep.mkdir(parents=True)
    assert project_root([deep / "alpha.moos"], cwd=str(tmp_path)) == str(tmp_path / "repo")


def test_working_folder_when_paths_lie_under_it(tmp_path):
    deep = tmp_path / "tarball" / "missions"
    deep.mkdir(parents=True)
    assert project_root([deep], cwd=str(tmp_path / "tarball")) == str(tmp_path / "tarball")


def test_common_folder_of_paths_outside_the_working_folder(tmp_path):
    a = tmp_path / "x" / "one"
    b = tmp_path / "x" / "two"
    a.mkdir(parents=True)
    b.mkdir()
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    got = project_root([a / "m.moos", b / "n.moos"], cwd=str(elsewhere))
    assert got == str(tmp_path / "x")


def test_within_is_by_path_component(tmp_path):
    assert is_within(str(tmp_path / "a" / "b"), str(tmp_path / "a"))
    assert not is_within(str(tmp_path / "ab"), str(tmp_path / "a"))


def test_real_within_follows_links(tmp_path):
    root = tmp_path / "root"
    root.mkdir()
    outside = tmp_path / "secret.txt"
    outside.write_text("x")
    link = root / "pw.moos"
    os.symlink(outside, link)
    assert is_within(str(link), str(root))
    assert not real_within(str(link), str(root))
