"""Results back in the city model: ``export --run`` puts each building's simulated heating and
cooling need, per m2 and peak loads, and the same per zone, into the exported CityJSON, as
attributes the shipped Energy extension declares (issue 16, item 5)."""
import json

import jsonschema
import pytest

from export_helpers import EPW, shifted
from factories import gabled_house
from lod2energy.exporters import energyplus
from lod2energy.exporters.cityjson import writer as X
from lod2energy.exporters.cityjson import schema as CS
from lod2energy.exporters import run_results as R
from lod2energy.io import cityjson_write
from lod2energy.model import CityModel, frozen_mapping


def _house_file(tmp_path):
    b = shifted(gabled_house(eaves=5.6, ridge=9.0), (212000.0, 490000.0, 0.0))  # near Heino, the weather file
    model = CityModel(version="2.0", metadata=frozen_mapping({"referenceSystem":
                                                              "https://www.opengis.net/def/crs/EPSG/0/28992"}))
    path = tmp_path / "house.city.json"
    cityjson_write.write(str(path), model, [b])
    return path


@pytest.mark.parametrize("v", ("1.0", "1.1", "2.0"))
def test_result_attributes_are_declared_by_the_shipped_extension(v):
    ext = CS.extension_schema(v)["extraAttributes"]["Building"]
    for name in list(R.ATTRIBUTES.values()) + [R.ZONES_ATTRIBUTE]:
        assert name in ext
    b = shifted(gabled_house(), (0.0, 0.0, 0.0)).with_provenance(run_results={
        "building": {"heating_kwh": 10.0, "cooling_kwh": 0.0, "heating_kwh_m2": 1.0, "cooling_kwh_m2": 0.0,
                     "heating_peak_w": None, "cooling_peak_w": 5.0, "floor_area_m2": 10.0},
        "zones": {"Z1": {"heating_kwh": 10.0, "cooling_kwh": 0.0, "heating_kwh_m2": 1.0, "cooling_kwh_m2": 0.0,
                         "heating_peak_w": None, "cooling_peak_w": 5.0, "floor_area_m2": 10.0}}})
    attrs = R.result_attributes(b)
    for k, val in attrs.items():
        jsonschema.Draft7Validator(ext[k]).validate(val)
    bad = dict(attrs[R.ZONES_ATTRIBUTE]["Z1"], heatingDemand=-1.0)
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.Draft7Validator(ext[R.ZONES_ATTRIBUTE]).validate({"Z1": bad})


def test_no_run_no_result_attributes(tmp_path):
    from lod2energy.cli import main
    src = _house_file(tmp_path)
    out = tmp_path / "out"
    assert main(["export", str(src), "-o", str(out), "--idf", "--cityjson", "-q", "--no-html"]) == 0
    doc = json.loads((out / "house.energy.city.json").read_text())
    attrs = doc["CityObjects"]["house"]["attributes"]
    assert not any(k in attrs for k in R.ATTRIBUTES.values())
    assert "results" not in json.loads((out / "report.json").read_text())["buildings"][0]["exports"]["idf"]


@pytest.mark.external
def test_export_run_puts_the_results_in_the_cityjson(tmp_path):
    if energyplus.run.binary() is None:
        pytest.skip("EnergyPlus not installed")
    from lod2energy.cli import main
    src = _house_file(tmp_path)
    out = tmp_path / "out"
    rc = main(["export", str(src), "-o", str(out), "--idf", "--cityjson", "--run", "--weather", str(EPW), "-q",
               "--no-html"])
    assert rc == 0
    report = json.loads((out / "report.json").read_text())
    (entry,) = report["buildings"]
    idf = entry["exports"]["idf"]
    res = idf["results"]
    path = out / "house.energy.city.json"
    doc = json.loads(path.read_text())
    attrs = doc["CityObjects"]["house"]["attributes"]
    # the building's figures, equal to the report's
    # the results are rounded to 0.01 kWh (energyplus.ZoneDemand.as_dict), heating_kwh is not
    assert attrs["+energyHeatingDemand"] == pytest.approx(idf["heating_kwh"], abs=0.006)
    assert attrs["+energyCoolingDemand"] == pytest.approx(idf["cooling_kwh"], abs=0.006)
    for key, name in R.ATTRIBUTES.items():
        assert attrs[name] == res["building"][key]
    assert attrs["+energyHeatingDemand"] > 0 and attrs["+energyHeatingPeakLoad"] > 0
    assert 20 < attrs["+energyHeatingDemandPerFloorArea"] < 400
    # per zone: the storeys (the unconditioned attic has no HVAC), summing to the building
    zones = attrs["+energyThermalZones"]
    assert set(zones) == set(res["zones"]) == {"house_S1", "house_S2"}
    for z, d in zones.items():
        assert d["heatingDemand"] == res["zones"][z]["heating_kwh"]
        assert d["conditionedFloorArea"] == res["zones"][z]["floor_area_m2"]
    assert sum(d["heatingDemand"] for d in zones.values()) == pytest.approx(attrs["+energyHeatingDemand"], abs=0.05)
    # the file is schema-valid, the extension's attributes included (declared and valid)
    assert X.self_check(str(path)) == []
    ext = json.loads((out / "energy.ext.json").read_text())
    for k, v in attrs.items():
        if k.startswith("+energy"):
            jsonschema.Draft7Validator(ext["extraAttributes"]["Building"][k]).validate(v)
    doc["CityObjects"]["house"]["attributes"]["+energyHeatingDemand"] = -5.0
    bad = tmp_path / "bad" / "house.energy.city.json"
    bad.parent.mkdir()
    bad.write_text(json.dumps(doc))
    assert any("+energyHeatingDemand" in p for p in X.self_check(str(bad), extension=ext))
