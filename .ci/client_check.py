"""Calls every route of a running thrustline through the Python client that openapi-python-client
generated from the committed openapi/openapi.json, with typed models, and checks the answers
against the published values (SPEC §1.4, §2.3) — what an integrator's first script would do.

Usage: python3 .ci/client_check.py BASE_URL GENERATED_CLIENT_DIR
"""
import sys

base_url, generated = sys.argv[1], sys.argv[2]
sys.path.insert(0, generated)

from thrustline_client import Client  # noqa: E402
from thrustline_client.api.arch import (  # noqa: E402
    dead_load, dead_load_svg, live_load, live_load_svg, minimum_thickness)
from thrustline_client.api.service import healthz  # noqa: E402
from thrustline_client.api.slope import spencer, spencer_svg  # noqa: E402
from thrustline_client.models import (  # noqa: E402
    CircleDto, CircularGeometry, CircularGeometryDto, CircularGeometryKind, CircularKind,
    DeadLoadRequest, DeadLoadResponse, HingeSideDto, LiveLoadRequest, LiveLoadResponse, LoadDto,
    MinimumThicknessOutcomeDto, MinimumThicknessRequest, MinimumThicknessResponse, Problem,
    ResultantDto, SearchDto, SlopeDto, SoilDto, SpencerRequest, SpencerResponse,
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
    return CircularGeometry(kind=CircularGeometryKind.CIRCULAR, radius=10.0,
                            thickness=thickness, voussoirs=voussoirs)


health = healthz.sync(client=client)
check("healthz", health is not None and health.status == "ok", health)

# Milankovitch, N = 1800: D = 1.0747 collapses in the thesis' five hinges (SPEC §1.4).
answer = dead_load.sync(client=client, body=DeadLoadRequest(geometry=semicircle(1.0747, 1800)))
check("dead load is typed", isinstance(answer, DeadLoadResponse), answer)
if isinstance(answer, DeadLoadResponse):
    check("Milankovitch 1.0747 falls", answer.dead_load_factor == 0.0 and answer.stable is False)
    hinges = [(a.interface, a.resultant, a.hinge) for a in answer.active_constraints]
    expected = [(1, ResultantDto.S, HingeSideDto.EXTRADOS), (356, ResultantDto.Q, HingeSideDto.INTRADOS),
                (901, ResultantDto.S, HingeSideDto.EXTRADOS), (1446, ResultantDto.Q, HingeSideDto.INTRADOS),
                (1801, ResultantDto.S, HingeSideDto.EXTRADOS)]
    check("five hinges as the thesis prints them", hinges == expected, hinges)

# Live load near the quarter span: λ = 22.99688965 (README, checked against HiGHS).
answer = live_load.sync(client=client, body=LiveLoadRequest(
    geometry=semicircle(1.5, 100), loads=[LoadDto(block=26, fy=-1.0)]))
check("live load is typed", isinstance(answer, LiveLoadResponse), answer)
if isinstance(answer, LiveLoadResponse):
    check("quarter-span load factor", abs(answer.load_factor - 22.996889652) < 1e-6, answer.load_factor)

# Minimum thickness, N = 1800: 0.10747 < d/R < 0.10748 (SPEC §1.4).
answer = minimum_thickness.sync(client=client, body=MinimumThicknessRequest(
    geometry=CircularGeometryDto(kind=CircularKind.CIRCULAR, radius=10.0, voussoirs=1800)))
check("minimum thickness is typed", isinstance(answer, MinimumThicknessResponse), answer)
if isinstance(answer, MinimumThicknessResponse):
    check("Milankovitch's d/R", answer.outcome == MinimumThicknessOutcomeDto.FOUND
          and 0.10747 <= answer.thickness_to_radius <= 0.10748, answer.thickness_to_radius)

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

print(f"client: {passed} passed, {failed} failed")
sys.exit(1 if failed else 0)
