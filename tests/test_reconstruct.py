"""The demonstration tables: deterministic, consistent with the config and with Table 2."""

from pathlib import Path

import jsonschema
import numpy as np
import pandas as pd
import pytest
import yaml

from demo import reconstruct as rec
from demid.design import model_matrix, quadratic_terms
from demid.spec import MaterialSpec
from demid.surrogate import fit_response

ROOT = Path(__file__).resolve().parent.parent
CONFIG = yaml.safe_load((ROOT / "config.yaml").read_text(encoding="utf-8"))


@pytest.fixture(scope="module")
def tables():
    return {name: pd.read_csv(ROOT / "data" / "ccd" / f"{name}.csv") for name in rec.MATERIALS}


def test_csvs_regenerate_byte_for_byte(tmp_path):
    written = rec.reconstruct(tmp_path)
    assert sorted(written) == sorted(rec.MATERIALS)
    for name, path in written.items():
        assert path.read_bytes() == (ROOT / "data" / "ccd" / f"{name}.csv").read_bytes(), name


def test_refit_reproduces_table2(tables):
    for name, material in rec.MATERIALS.items():
        for response in material.responses:
            stats = fit_response(tables[name], material.factor_names, response.name, alpha=material.alpha).statistics()
            assert stats.r2 == pytest.approx(response.r2, abs=5e-4), (name, response.name)
            assert stats.rmse == pytest.approx(response.rmse, rel=5e-3), (name, response.name)
            # the residuals carry the RMSE exactly (up to the 6 written decimals)
            assert stats.rmse == pytest.approx(response.rmse, rel=1e-6)


def test_refit_recovers_the_chosen_surrogates(tables):
    for name, material in rec.MATERIALS.items():
        for response in material.responses:
            fitted = fit_response(tables[name], material.factor_names, response.name).surrogate()
            chosen = rec.response_polynomial(material, response.name)
            x = np.array([[f.lower for f in material.factors], [f.upper for f in material.factors],
                          [f.center for f in material.factors]])
            np.testing.assert_allclose(fitted.predict(x), model_matrix(x, quadratic_terms(len(x[0]))) @ chosen,
                                       rtol=1e-7)


def test_tables_follow_the_declared_design(tables):
    for name, material in rec.MATERIALS.items():
        table = tables[name]
        k = len(material.factors)
        assert list(table.columns) == ["run", *material.factor_names, *[r.name for r in material.responses]]
        assert sorted(table["run"]) == list(range(1, 2 ** k + 2 * k + material.center_runs + 1))
        coded = material.to_coded(table[material.factor_names].to_numpy())
        radius = np.sort(np.round(np.abs(coded), 4).ravel())
        assert set(np.unique(radius)) <= {0.0, 1.0, round(material.alpha, 4)}
        assert int(np.sum(np.all(coded == 0, axis=1))) == material.center_runs
        for factor in material.factors:
            assert table[factor.name].min() == factor.lower and table[factor.name].max() == factor.upper


def test_config_matches_the_reconstruction():
    schema = yaml.safe_load((ROOT / "demid" / "schemas" / "config.schema.yaml").read_text(encoding="utf-8"))
    jsonschema.Draft7Validator(schema).validate(CONFIG)
    for name, material in rec.MATERIALS.items():
        cfg = CONFIG["materials"][name]
        assert cfg["data"] == f"data/ccd/{name}.csv"
        assert cfg["design"]["center_runs"] == material.center_runs
        assert cfg["design"]["alpha"] == pytest.approx(material.alpha, abs=1e-5)
        assert list(cfg["factors"]) == material.factor_names
        for factor in material.factors:
            assert (cfg["factors"][factor.name]["lower"], cfg["factors"][factor.name]["upper"]) == \
                (factor.lower, factor.upper)
        for response in material.responses:
            rc = cfg["responses"][response.name]
            assert rc["published"]["r2"] == response.r2 and rc["published"]["rmse"] == response.rmse
            if np.isfinite(response.target):
                assert rc["target"] == response.target


def test_tables_pass_transcription_validation():
    from demid.config import load_config
    from demid.data import validate_material

    from demid.transcription import check_table

    config = load_config(ROOT / "config.yaml", base_dir=ROOT)
    for name, material in config["materials"].items():
        checked = validate_material(MaterialSpec.from_material(name, material), base_dir=ROOT)
        assert checked.warnings == []
        printed = pd.read_csv(ROOT / material["data"], dtype=str)
        results = check_table(checked.table, list(material["factors"]), material["responses"],
                              alpha=material["design"]["alpha"], printed=printed)
        assert len(results) == len(material["responses"])
        assert all(r.consistent for r in results), [r.message for r in results]


def test_stroke_order_and_positive_crack_index(tables):
    mortar = tables["mortar"]
    assert (mortar["d5"] < mortar["d10"]).all() and (mortar["d10"] < mortar["d15"]).all()
    assert (tables["paste"]["S"] > 0).all()


def test_orthogonal_residuals():
    rng = np.random.default_rng(3)
    x = rng.uniform(-1, 1, size=(13, 2))
    model = model_matrix(x, quadratic_terms(2))
    e = rec.orthogonal_residuals(model, 0.969, rng.standard_normal(13))
    np.testing.assert_allclose(model.T @ e, 0.0, atol=1e-12)
    assert np.sqrt(np.mean(e ** 2)) == pytest.approx(0.969, rel=1e-12)


def test_exact_set_2d_known_shapes():
    # band |w| <= 0.1 over [-1, 1]^2: fraction 0.1, full u, w in [-0.1, 0.1]
    frac, lower, upper = rec.exact_set_2d([np.array([0, 0, 1.0, 0, 0, 0])], 0.1, [-1, -1], [1, 1])
    assert frac == pytest.approx(0.1, rel=1e-9)
    np.testing.assert_allclose(lower, [-1, -0.1], atol=1e-9)
    np.testing.assert_allclose(upper, [1, 0.1], atol=1e-9)
    # annulus 0.2 <= u² + w² <= 0.3: area 0.1 pi out of 4
    frac, lower, upper = rec.exact_set_2d([np.array([-0.25, 0, 0, 0, 1.0, 1.0])], 0.05, [-1, -1], [1, 1])
    assert frac == pytest.approx(0.1 * np.pi / 4, rel=1e-5)
    np.testing.assert_allclose(upper, [np.sqrt(0.3)] * 2, atol=1e-9)


def test_exact_geometry_agrees_with_the_pipeline_grid():
    material = rec.MATERIALS["poraver"]
    rhos = {k: np.array(v) for k, v in rec.RHO["poraver"].items()}
    lo, hi = rec._coded_box(material)
    frac, low, up = rec.exact_set_2d([rhos["aor"]], 0.01, lo, hi)
    grid = rec.grid_sets(material, rhos, {"a": (["aor"], 0.01)}, 1001)["a"]
    assert grid.fraction == pytest.approx(frac, rel=1e-4)
    np.testing.assert_allclose(grid.lower, rec._to_actual(material, low), atol=5e-5)
    np.testing.assert_allclose(grid.upper, rec._to_actual(material, up), atol=5e-5)


def test_paste_crack_index_follows_from_the_diameter():
    rho_d = np.array(rec.RHO["paste"]["D"])
    np.testing.assert_allclose(rec.paste_s_shape(rho_d), rec.RHO["paste"]["S"], rtol=1e-8, atol=1e-9)
    # P1 is where the diameter error reaches 2 %
    p1 = rec.MATERIALS["paste"].to_coded(np.array(rec.PASTE_P1))
    assert float(model_matrix(p1, quadratic_terms(3))[0] @ rho_d) == pytest.approx(-0.02, abs=2e-4)


def test_mortar_reference_point_just_outside_the_full_sequence_set():
    material = rec.MATERIALS["mortar"]
    sets = rec.grid_sets(material, {k: np.array(v) for k, v in rec.RHO["mortar"].items()},
                         {"full": (["d5", "d10", "d15"], 0.02)}, 401)
    z = material.to_coded(np.array([0.2, 6.4]))
    errors = [abs(float(model_matrix(z, quadratic_terms(2))[0] @ np.array(rec.RHO["mortar"][r])))
              for r in ("d5", "d10", "d15")]
    assert 0.02 < max(errors) < 0.025
    assert sets["full"].upper[0] < 0.2 and sets["full"].upper[1] == pytest.approx(6.4, abs=0.01)


def test_exact_set_3d_known_shapes():
    # slab |c| <= 0.1 in [-1, 1]^3, i.e. rho = c (coefficient of the third factor)
    slab = np.zeros(10)
    slab[3] = 1.0
    frac, lower, upper = rec.exact_set_3d(slab, 0.1, [-1] * 3, [1] * 3, n=21)
    assert frac == pytest.approx(0.1, rel=1e-9)
    np.testing.assert_allclose(lower, [-1, -1, -0.1], atol=1e-9)
    np.testing.assert_allclose(upper, [1, 1, 0.1], atol=1e-9)
    # ball a² + b² + c² <= 0.25 (rho = a² + b² + c² - 0.125, eps 0.125): volume pi/6 * 0.125 out of 8
    ball = np.array([-0.125, 0, 0, 0, 0, 0, 0, 1.0, 1.0, 1.0])
    frac, lower, upper = rec.exact_set_3d(ball, 0.125, [-1] * 3, [1] * 3, n=201)
    assert frac == pytest.approx(4 / 3 * np.pi * 0.5 ** 3 / 8, rel=1e-3)
    np.testing.assert_allclose(upper, [0.5] * 3, atol=1e-3)
    assert rec.exact_set_3d(ball, 0.125, [-1] * 3, [1] * 3, n=51, spans=False)[1] is None
