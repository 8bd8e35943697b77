"""A C-source FMU (FMI 2.0, co-simulation) of the friction map, built on the C header.

The archive holds ``modelDescription.xml``, the C header that
:func:`ballscrew.report.friction_files.c_header` writes and a C file with the
FMI 2.0 functions around it: three inputs, the motor speed [rad/s], the axial
load [N] and the temperature [°C], and one output, the motor-side friction
torque [N·m] that the header's interpolation gives. It carries no binary: an
importing tool compiles the sources for its own platform (FMPy does it with
CMake; the FMI 2.0 headers come from the importer, as the standard provides).
"""

from __future__ import annotations

import hashlib
import io
import zipfile
from xml.sax.saxutils import escape

from ..fit.friction_map import FrictionMap

__all__ = ["MODEL_IDENTIFIER", "fmu_bytes"]

MODEL_IDENTIFIER = "BallScrewFriction"
"""The FMU's model identifier (the shared library's name once compiled)."""

_SOURCE = r"""/* ballscrew: FMI 2.0 co-simulation wrapper of the map in ballscrew_friction_map.h.
 * Inputs (value references): 0 motor speed [rad/s], 1 axial load [N], 2 temperature [degC];
 * output: 3 motor-side friction torque [N*m], signed like the speed. */
#include <stdlib.h>
#include <string.h>
#include "fmi2Functions.h"
#include "ballscrew_friction_map.h"

typedef struct { double u[3]; fmi2CallbackFunctions cb; } Instance;

static double output(const Instance *s) { return bs_friction_torque(s->u[0], s->u[1], s->u[2]); }

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean on, size_t n, const fmi2String c2[])
{ (void)c; (void)on; (void)n; (void)c2; return fmi2OK; }

fmi2Component fmi2Instantiate(fmi2String name, fmi2Type type, fmi2String guid,
                              fmi2String location, const fmi2CallbackFunctions *functions,
                              fmi2Boolean visible, fmi2Boolean logging)
{
    Instance *s;
    (void)name; (void)location; (void)visible; (void)logging;
    if (type != fmi2CoSimulation || guid == NULL || strcmp(guid, "@GUID@") != 0) return NULL;
    s = (Instance *)calloc(1, sizeof(Instance));
    if (s == NULL) return NULL;
    s->u[2] = @T0@;
    if (functions != NULL) s->cb = *functions;
    return s;
}

void fmi2FreeInstance(fmi2Component c) { free(c); }
fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean a, fmi2Real b, fmi2Real d,
                               fmi2Boolean e, fmi2Real f)
{ (void)c; (void)a; (void)b; (void)d; (void)e; (void)f; return fmi2OK; }
fmi2Status fmi2EnterInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2ExitInitializationMode(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Terminate(fmi2Component c) { (void)c; return fmi2OK; }
fmi2Status fmi2Reset(fmi2Component c)
{ Instance *s = (Instance *)c; s->u[0] = 0.0; s->u[1] = 0.0; s->u[2] = @T0@; return fmi2OK; }

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n, fmi2Real v[])
{
    const Instance *s = (const Instance *)c;
    size_t i;
    for (i = 0; i < n; i++) {
        if (vr[i] < 3) v[i] = s->u[vr[i]];
        else if (vr[i] == 3) v[i] = output(s);
        else return fmi2Error;
    }
    return fmi2OK;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                       const fmi2Real v[])
{
    Instance *s = (Instance *)c;
    size_t i;
    for (i = 0; i < n; i++) {
        if (vr[i] >= 3) return fmi2Error;
        s->u[vr[i]] = v[i];
    }
    return fmi2OK;
}

#define UNSUPPORTED_GET(name, type) \
fmi2Status name(fmi2Component c, const fmi2ValueReference vr[], size_t n, type v[]) \
{ (void)c; (void)vr; (void)v; return n == 0 ? fmi2OK : fmi2Error; }
#define UNSUPPORTED_SET(name, type) \
fmi2Status name(fmi2Component c, const fmi2ValueReference vr[], size_t n, const type v[]) \
{ (void)c; (void)vr; (void)v; return n == 0 ? fmi2OK : fmi2Error; }
UNSUPPORTED_GET(fmi2GetInteger, fmi2Integer)
UNSUPPORTED_GET(fmi2GetBoolean, fmi2Boolean)
UNSUPPORTED_GET(fmi2GetString, fmi2String)
UNSUPPORTED_SET(fmi2SetInteger, fmi2Integer)
UNSUPPORTED_SET(fmi2SetBoolean, fmi2Boolean)
UNSUPPORTED_SET(fmi2SetString, fmi2String)

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *st)
{ (void)c; (void)st; return fmi2Error; }
fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate st)
{ (void)c; (void)st; return fmi2Error; }
fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *st)
{ (void)c; (void)st; return fmi2Error; }
fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate st, size_t *n)
{ (void)c; (void)st; (void)n; return fmi2Error; }
fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate st, fmi2Byte b[], size_t n)
{ (void)c; (void)st; (void)b; (void)n; return fmi2Error; }
fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte b[], size_t n, fmi2FMUstate *st)
{ (void)c; (void)b; (void)n; (void)st; return fmi2Error; }
fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference u[], size_t nu,
                                        const fmi2ValueReference z[], size_t nz,
                                        const fmi2Real dv[], fmi2Real dz[])
{ (void)c; (void)u; (void)nu; (void)z; (void)nz; (void)dv; (void)dz; return fmi2Error; }
fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                       const fmi2Integer o[], const fmi2Real v[])
{ (void)c; (void)vr; (void)n; (void)o; (void)v; return fmi2Error; }
fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t n,
                                        const fmi2Integer o[], fmi2Real v[])
{ (void)c; (void)vr; (void)n; (void)o; (void)v; return fmi2Error; }
fmi2Status fmi2DoStep(fmi2Component c, fmi2Real t, fmi2Real h, fmi2Boolean flag)
{ (void)c; (void)t; (void)h; (void)flag; return fmi2OK; }
fmi2Status fmi2CancelStep(fmi2Component c) { (void)c; return fmi2Error; }
fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind k, fmi2Status *v)
{ (void)c; (void)k; (void)v; return fmi2Discard; }
fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind k, fmi2Real *v)
{ (void)c; (void)k; (void)v; return fmi2Discard; }
fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind k, fmi2Integer *v)
{ (void)c; (void)k; (void)v; return fmi2Discard; }
fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind k, fmi2Boolean *v)
{ (void)c; (void)k; (void)v; return fmi2Discard; }
fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind k, fmi2String *v)
{ (void)c; (void)k; (void)v; return fmi2Discard; }
"""


def _model_description(m: FrictionMap, version: str, guid: str) -> str:
    t0 = float(m.temperatures[0])
    description = escape(f"friction map of {m.model} for '{m.case_title}' (ballscrew {version})")
    variables = [
        ("motor_speed", 0, "input", "rad/s", 0.0, "motor speed, > 0 moves the nut towards +x"),
        ("axial_load", 1, "input", "N", 0.0, "force of the load on the nut along x"),
        ("temperature", 2, "input", "degC", t0, "lubricant temperature"),
    ]
    rows = [
        f'  <ScalarVariable name="{n}" valueReference="{vr}" causality="{c}" '
        f'variability="continuous" description="{escape(d)}">\n'
        f'   <Real unit="{u}" start="{s!r}"/>\n  </ScalarVariable>'
        for n, vr, c, u, s, d in variables
    ]
    rows.append(
        '  <ScalarVariable name="friction_torque" valueReference="3" causality="output" '
        'variability="continuous" initial="calculated" description="motor-side friction '
        'torque, signed like the speed">\n   <Real unit="N.m"/>\n  </ScalarVariable>'
    )
    units = "".join(f'  <Unit name="{u}"/>\n' for u in ("rad/s", "N", "degC", "N.m"))
    return f"""<?xml version="1.0" encoding="UTF-8"?>
<fmiModelDescription fmiVersion="2.0" modelName="{MODEL_IDENTIFIER}" guid="{guid}"
 description="{description}" generationTool="ballscrew {escape(version)}"
 variableNamingConvention="flat" numberOfEventIndicators="0">
 <CoSimulation modelIdentifier="{MODEL_IDENTIFIER}" canHandleVariableCommunicationStepSize="true">
  <SourceFiles>
   <File name="ballscrew_friction_fmu.c"/>
  </SourceFiles>
 </CoSimulation>
 <UnitDefinitions>
{units} </UnitDefinitions>
 <ModelVariables>
{chr(10).join(rows)}
 </ModelVariables>
 <ModelStructure>
  <Outputs>
   <Unknown index="4" dependencies="1 2 3"/>
  </Outputs>
 </ModelStructure>
</fmiModelDescription>
"""


def _entry(archive: zipfile.ZipFile, name: str, data: bytes) -> None:
    """A member with a fixed date, so that the same map gives the same bytes."""
    info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
    info.compress_type = zipfile.ZIP_DEFLATED
    archive.writestr(info, data)


def fmu_bytes(m: FrictionMap, version: str, header: bytes) -> bytes:
    """The FMU archive of the map (module docstring) around its C ``header``, reproducibly.

    ``header`` is :func:`ballscrew.report.friction_files.c_header` of the map, handed
    in so that this module does not import the one that imports it.
    """
    digest = hashlib.sha256(header).hexdigest()
    guid = f"{{{digest[:8]}-{digest[8:12]}-{digest[12:16]}-{digest[16:20]}-{digest[20:32]}}}"
    source = _SOURCE.replace("@GUID@", guid).replace("@T0@", repr(float(m.temperatures[0])))
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        _entry(archive, "modelDescription.xml", _model_description(m, version, guid).encode())
        _entry(archive, "sources/ballscrew_friction_map.h", header)
        _entry(archive, "sources/ballscrew_friction_fmu.c", source.encode())
    return buffer.getvalue()
