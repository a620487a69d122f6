"""A table the config names outside the study folder (absolute, ``../``, or a link inside the folder pointing out)
that is not a valid table: the error names the folder and the file's real place and shows none of its content; a
bad table inside the folder keeps its own error, content and all."""

from __future__ import annotations

import pytest

from demid.data import content_hidden_outside, validate_material
from demid.errors import InputError
from demid.spec import MaterialSpec

SECRET = "SECRET-LINE,hunter2\nsecond,SECRET\n"


def _spec(data):
    return MaterialSpec.from_material("m", {
        "data": data, "design": {"type": "custom"}, "responses": {"y": {"target": 1.0}},
        "factors": {"x1": {"lower": 0.0, "upper": 1.0}, "x2": {"lower": 0.0, "upper": 1.0}}})


def _error(data, study):
    with pytest.raises(InputError) as info:
        with content_hidden_outside(data, study):
            validate_material(_spec(data), base_dir=study)
    return str(info.value)


@pytest.mark.parametrize("how", ["absolute", "relative", "link"])
def test_a_bad_table_outside_the_study_is_named_without_its_content(tmp_path, how):
    study = tmp_path / "study"
    (study / "data").mkdir(parents=True)
    secret = tmp_path / "secret.csv"
    secret.write_text(SECRET, encoding="utf-8")
    data = {"absolute": str(secret), "relative": "../secret.csv", "link": "data/link.csv"}[how]
    if how == "link":
        (study / "data" / "link.csv").symlink_to(secret)
    text = _error(data, study)
    assert text == (f"{data}: not a valid table of this material, and its content is not shown: it lies outside the "
                    f"study folder {study.resolve()} (at {secret.resolve()}); copy the table into the study folder to "
                    "see what is wrong")


def test_a_bad_table_inside_the_study_keeps_its_own_error(tmp_path):
    (tmp_path / "data").mkdir()
    (tmp_path / "data" / "t.csv").write_text(SECRET, encoding="utf-8")
    with pytest.raises(InputError) as info:
        validate_material(_spec("data/t.csv"), base_dir=tmp_path)
    assert _error("data/t.csv", tmp_path) == str(info.value)
    assert "outside the study folder" not in str(info.value) and "hunter2" in str(info.value)
