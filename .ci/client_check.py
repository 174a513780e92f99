"""Calls every route of a running thrustline through the Python client that openapi-python-client
generated from the committed openapi/openapi.json, with typed models, and checks the answers
against the published values (model §1.4, §2.3) — what an integrator's first script would do.

Usage: python3 .ci/client_check.py BASE_URL GENERATED_CLIENT_DIR
"""
import json
import pathlib
import sys

base_url, generated = sys.argv[1], sys.argv[2]
sys.path.insert(0, generated)

from thrustline_client import Client  # noqa: E402
from thrustline_client.api.arch import (  # noqa: E402
    dead_load, dead_load_csv, dead_load_report, dead_load_svg, live_load, live_load_csv,
    live_load_report, live_load_svg, minimum_thickness, minimum_thickness_csv)
from thrustline_client.api.service import batch, healthz, metrics  # noqa: E402
from thrustline_client.api.slope import (  # noqa: E402
    spencer, spencer_csv, spencer_report, spencer_svg)
from thrustline_client.models import (  # noqa: E402
    CircleDto, CircularGeometryDto, CircularKind,
    ArchTableDto, BatchAnswer, BatchLine, BatchLineBody, BatchRoute, DeadLoadRequest, DeadLoadResponse, HingeSideDto, LiveLoadRequest, LiveLoadResponse, LoadDto,
    MinimumThicknessOutcomeDto, MinimumThicknessRequest, MinimumThicknessResponse, Problem,
    MinimumThicknessTableDto, ResultantDto, SearchDto, SlopeDto, SlopeTableDto, SoilDto, SpencerRequest, SpencerResponse,
    SpencerStatusDto)

client = Client(base_url=base_url, raise_on_unexpected_status=True, timeout=60)
passed = failed = 0


def check(name, condition, detail=""):
    global passed, failed
    if condition:
        passed += 1
        print(f"ok: {name}")
    else:
        failed += 1
        print(f"FAILED: {name} {detail}")


def semicircle(thickness, voussoirs):
    return CircularGeometryDto(kind=CircularKind.CIRCULAR, radius=10.0,
                               thickness=thickness, voussoirs=voussoirs)


health = healthz.sync(client=client)
check("healthz", health is not None and health.status == "ok", health)

# Milankovitch, N = 1800: D = 1.0747 collapses in the thesis' five hinges (model §1.4).
answer = dead_load.sync(client=client, body=DeadLoadRequest(geometry=semicircle(1.0747, 1800)))
check("dead load is typed", isinstance(answer, DeadLoadResponse), answer)
if isinstance(answer, DeadLoadResponse):
    check("Milankovitch 1.0747 falls", answer.dead_load_factor == 0.0 and answer.stable is False)
    hinges = [(a.interface, a.resultant, a.hinge) for a in answer.active_constraints]
    expected = [(1, ResultantDto.S, HingeSideDto.EXTRADOS), (356, ResultantDto.Q, HingeSideDto.INTRADOS),
                (901, ResultantDto.S, HingeSideDto.EXTRADOS), (1446, ResultantDto.Q, HingeSideDto.INTRADOS),
                (1801, ResultantDto.S, HingeSideDto.EXTRADOS)]
    check("five hinges as the thesis prints them", hinges == expected, hinges)

# Live load near the quarter span: λ = 22.99688965 (docs/arches.md, checked against HiGHS).
answer = live_load.sync(client=client, body=LiveLoadRequest(
    geometry=semicircle(1.5, 100), loads=[LoadDto(block=26, fy=-1.0)]))
check("live load is typed", isinstance(answer, LiveLoadResponse), answer)
if isinstance(answer, LiveLoadResponse):
    check("quarter-span load factor", abs(answer.load_factor - 22.996889652) < 1e-6, answer.load_factor)

# Minimum thickness, N = 1800: 0.10747 < d/R < 0.10748 (model §1.4); the same circular geometry
# type as the other arch routes, its thickness the D of the geometric factor of safety.
answer = minimum_thickness.sync(client=client, body=MinimumThicknessRequest(
    geometry=semicircle(1.5, 1800)))
check("minimum thickness is typed", isinstance(answer, MinimumThicknessResponse), answer)
if isinstance(answer, MinimumThicknessResponse):
    check("Milankovitch's d/R", answer.outcome == MinimumThicknessOutcomeDto.FOUND
          and 0.10747 <= answer.thickness_to_radius <= 0.10748, answer.thickness_to_radius)
    check("geometric factor 1.5 / 1.0748", abs(answer.geometric_factor_of_safety - 1.5 / 1.0748) < 1e-4,
          answer.geometric_factor_of_safety)

# Spencer (1967) example, 100 slices: F = 1.06958, θ = 22.432° (thesis table).
soil = SoilDto(unit_weight=10.0, cohesion=6.096, friction_angle_deg=40.0, pore_pressure_ratio=0.5)
slope = SlopeDto(height=30.48, length=60.96)
answer = spencer.sync(client=client, body=SpencerRequest(
    slope=slope, soil=soil, circle=CircleDto(x=9.63168, y=63.76416), slices=100))
check("spencer is typed", isinstance(answer, SpencerResponse), answer)
if isinstance(answer, SpencerResponse):
    check("Spencer's F and θ", answer.status == SpencerStatusDto.CONVERGED
          and abs(answer.factor_of_safety - 1.06958) <= 5e-6 and abs(answer.theta_deg - 22.432) <= 5e-4,
          (answer.factor_of_safety, answer.theta_deg))
answer = spencer.sync(client=client, body=SpencerRequest(slope=slope, soil=soil, search=SearchDto(), slices=50))
if isinstance(answer, SpencerResponse):
    check("critical circle below the example circle", answer.factor_of_safety < 1.0696
          and len(answer.grid.xs) == 21, answer.factor_of_safety)
else:
    check("search is typed", False, answer)

# A bad request comes back as a typed Problem naming the field.
answer = spencer.sync(client=client, body=SpencerRequest(
    slope=slope, soil=soil, circle=CircleDto(x=9.63168, y=63.76416), slices=0))
check("422 is a typed Problem naming the field", isinstance(answer, Problem) and answer.field == "slices", answer)

# The drawings come back as text.
for name, route, body in [
        ("dead-load drawing", dead_load_svg, DeadLoadRequest(geometry=semicircle(1.0747, 60))),
        ("live-load drawing", live_load_svg, LiveLoadRequest(geometry=semicircle(1.5, 60), loads=[LoadDto(block=16, fy=-1.0)])),
        ("slope drawing", spencer_svg, SpencerRequest(slope=slope, soil=soil, circle=CircleDto(x=9.63168, y=63.76416)))]:
    svg = route.sync(client=client, body=body)
    check(name, isinstance(svg, str) and "<svg" in svg, type(svg))

# The reports come back as text: one HTML page with the published number in its headline.
for name, route, body, headline in [
        ("dead-load report", dead_load_report, DeadLoadRequest(geometry=semicircle(1.0747, 1800)),
         "Dead load: λ₀ = 0 (collapses)"),
        ("live-load report", live_load_report, LiveLoadRequest(geometry=semicircle(1.5, 100), loads=[LoadDto(block=26, fy=-1.0)]),
         "Live load: λ = 22.9969"),
        ("slope report", spencer_report, SpencerRequest(slope=slope, soil=soil, circle=CircleDto(x=9.63168, y=63.76416), slices=100),
         "F = 1.0696, θ = 22.43°")]:
    page = route.sync(client=client, body=body)
    check(name, isinstance(page, str) and page.startswith("<!DOCTYPE html>") and headline in page,
          page[:200] if isinstance(page, str) else page)
text = metrics.sync(client=client)
check("metrics as text", isinstance(text, str) and "thrustline_solves_running" in text, type(text))

# The tables come back as text, the table asked for by an enum.
for name, route, body, table, header in [
        ("dead-load hinges table", dead_load_csv, DeadLoadRequest(geometry=semicircle(1.0747, 1800)),
         ArchTableDto.HINGES, "interface,angle_deg,location"),
        ("live-load thrust-line table", live_load_csv, LiveLoadRequest(geometry=semicircle(1.5, 100), loads=[LoadDto(block=26, fy=-1.0)]),
         ArchTableDto.THRUST_LINE, "interface,x,y"),
        ("minimum-thickness hinges table", minimum_thickness_csv, MinimumThicknessRequest(geometry=semicircle(1.5, 60)),
         MinimumThicknessTableDto.HINGES, "interface,angle_deg"),
        ("slope slices table", spencer_csv, SpencerRequest(slope=slope, soil=soil, circle=CircleDto(x=9.63168, y=63.76416), slices=100),
         SlopeTableDto.SLICES, "slice,x_left,x_right")]:
    text = route.sync(client=client, body=body, table=table)
    lines = text.splitlines() if isinstance(text, str) else []
    check(name, len(lines) > 1 and lines[0].startswith(header), text if not lines else lines[:2])
# Milankovitch's five hinges, read from the CSV table as from the JSON answer.
text = dead_load_csv.sync(client=client, body=DeadLoadRequest(geometry=semicircle(1.0747, 1800)),
                          table=ArchTableDto.HINGES)
interfaces = [int(line.split(",")[0]) for line in text.splitlines()[1:]] if isinstance(text, str) else []
check("five hinges in the CSV table", interfaces == [1, 356, 901, 1446, 1801], interfaces)

# A batch of one line is typed (BatchLine in, BatchAnswer out); a fleet is NDJSON through the
# client's own httpx client, answered line by line in order.
answer = batch.sync(client=client, body=BatchLine(
    route=BatchRoute("/arch/dead-load"),
    body=BatchLineBody.from_dict(DeadLoadRequest(geometry=semicircle(1.0747, 1800)).to_dict())))
check("a one-line batch is typed", isinstance(answer, BatchAnswer) and answer.status == 200
      and answer.body["dead_load_factor"] == 0.0, answer)
fleet = [{"route": "/arch/dead-load", "body": {"geometry": semicircle(d, 1800).to_dict()}}
         for d in (1.0747, 1.0748)] + [{"route": "/slope/spencer", "body": {"slope": slope.to_dict(),
         "soil": soil.to_dict(), "circle": {"x": 9.63168, "y": 63.76416}, "slices": 100}}]
reply = client.get_httpx_client().post(
    "/batch", content="".join(json.dumps(line) + "\n" for line in fleet),
    headers={"content-type": "application/x-ndjson"})
lines = [BatchAnswer.from_dict(json.loads(text)) for text in reply.text.split("\n") if text]
check("a fleet in one batch: Milankovitch falls then stands, Spencer's F",
      [a.line for a in lines] == [1, 2, 3] and [a.status for a in lines] == [200, 200, 200]
      and lines[0].body["dead_load_factor"] == 0.0 and lines[1].body["dead_load_factor"] == 1.0
      and abs(lines[2].body["factor_of_safety"] - 1.06958) <= 5e-6,
      [(a.line, a.status) for a in lines])

# What pydantic's model_dump(), Jackson and System.Text.Json send: every optional field the
# client left unset as an explicit null, read from the spec's own schemas. Each route must
# accept it and answer exactly as without the nulls.
spec = json.loads((pathlib.Path(__file__).parent.parent / "openapi" / "openapi.json").read_text())
schemas = spec["components"]["schemas"]


def resolve(schema):
    while "$ref" in schema:
        schema = schemas[schema["$ref"].rsplit("/", 1)[-1]]
    return schema


def object_schema(value, schema):
    """The object schema a dict value is an instance of (through refs, nullable arms,
    discriminators and allOf)."""
    schema = resolve(schema)
    if "discriminator" in schema:
        d = schema["discriminator"]
        return object_schema(value, {"$ref": d["mapping"][value[d["propertyName"]]]})
    if "allOf" in schema:
        merged = {"properties": {}}
        for part in schema["allOf"]:
            merged["properties"].update(object_schema(value, part).get("properties", {}))
        merged["properties"].update(schema.get("properties", {}))
        return merged
    for arm in schema.get("oneOf", []) + schema.get("anyOf", []):
        arm = resolve(arm)
        if "properties" in arm or "discriminator" in arm or "allOf" in arm:
            return object_schema(value, arm)
    return schema


def with_nulls(value, schema):
    if isinstance(value, dict):
        props = object_schema(value, schema).get("properties", {})
        return {name: with_nulls(value[name], sub) if name in value else None
                for name, sub in props.items()}
    if isinstance(value, list):
        schema = resolve(schema)
        items = schema.get("items") or next(
            (resolve(a)["items"] for a in schema.get("oneOf", []) if "items" in resolve(a)), None)
        return [with_nulls(v, items) if items else v for v in value]
    return value


def timeless(answer):
    if isinstance(answer, dict):
        return {k: timeless(v) for k, v in answer.items() if "time" not in k}
    if isinstance(answer, list):
        return [timeless(v) for v in answer]
    return answer


raw = client.get_httpx_client()
for path, request, schema in [
        ("/arch/dead-load", DeadLoadRequest(geometry=semicircle(1.0747, 60)), "DeadLoadRequest"),
        ("/arch/live-load", LiveLoadRequest(geometry=semicircle(1.5, 60), loads=[LoadDto(block=16, fy=-1.0)]),
         "LiveLoadRequest"),
        ("/arch/minimum-thickness", MinimumThicknessRequest(geometry=semicircle(1.5, 12)),
         "MinimumThicknessRequest"),
        ("/slope/spencer", SpencerRequest(slope=slope, soil=soil, circle=CircleDto(x=9.63168, y=63.76416)),
         "SpencerRequest"),
        ("/slope/spencer", SpencerRequest(slope=slope, soil=soil, search=SearchDto(nx=5, ny=5), slices=20),
         "SpencerRequest")]:
    plain = request.to_dict()
    nulls = with_nulls(plain, {"$ref": f"#/components/schemas/{schema}"})
    sent_null = sum(1 for _ in json.dumps(nulls).split("null")) - 1
    first, second = raw.post(path, json=plain), raw.post(path, json=nulls)
    check(f"{path} with {sent_null} nulls", first.status_code == second.status_code == 200
          and sent_null > 0 and timeless(first.json()) == timeless(second.json()),
          (second.status_code, second.text[:300]))

print(f"client: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
