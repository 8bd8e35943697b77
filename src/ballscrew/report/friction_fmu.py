"""An FMU (FMI 2.0, co-simulation) of the friction map, built on the C header.

The archive holds ``modelDescription.xml``, the C header that
:func:`ballscrew.report.friction_files.c_header` writes and a C file with the
FMI 2.0 functions around it: three inputs, the motor speed [rad/s], the axial
load [N] and the temperature [°C], and one output, the motor-side friction
torque [N·m] that the header's interpolation gives.

The sources are always kept (``sources/``, listed under ``SourceFiles``), so
that any importer can compile them for its platform with the FMI 2.0 headers
it ships (FMPy: ``fmpy.build.build_platform_binary``). Where a C compiler is
found (:func:`find_compiler`: ``$CC``, then ``cc``, ``gcc``, ``clang``), the
export also compiles the shared library for the platform it runs on into
``binaries/<platform>/`` (FMI 2.0 §2.1.2 names the folders ``linux64``,
``darwin64``, ``win64``, ...), so that the file simulates as written there;
the compile uses :data:`FMI2_TYPES`, the standard's type and enum
declarations written out here. Without a compiler, or if the compile fails,
the FMU is the source FMU alone and :class:`FmuBuild` says so.

``ModelStructure`` lists the output under ``Outputs`` and, since its initial
value is calculated from the inputs, under ``InitialUnknowns`` with the three
inputs as its dependencies (FMI 2.0 §2.2.8).
"""

from __future__ import annotations

import hashlib
import io
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zipfile
from dataclasses import dataclass
from pathlib import Path
from xml.sax.saxutils import escape

from ..servo.friction_map import FrictionMap

__all__ = [
    "FMI2_TYPES", "MODEL_IDENTIFIER", "FmuBuild", "find_compiler", "fmi_platform", "fmu_build",
    "fmu_bytes",
]  # fmt: skip

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
  <InitialUnknowns>
   <Unknown index="4" dependencies="1 2 3"/>
  </InitialUnknowns>
 </ModelStructure>
</fmiModelDescription>
"""


def _entry(archive: zipfile.ZipFile, name: str, data: bytes) -> None:
    """A member with a fixed date, so that the same map gives the same bytes."""
    info = zipfile.ZipInfo(name, date_time=(1980, 1, 1, 0, 0, 0))
    info.compress_type = zipfile.ZIP_DEFLATED
    archive.writestr(info, data)


FMI2_TYPES = r"""/* The FMI 2.0 types, constants and enums the wrapper uses (FMI 2.0 section 2.1.2
 * and 2.1.3), declared for ballscrew's own compile of the binary; an importer that
 * compiles the sources uses the standard's headers instead. */
#ifndef BALLSCREW_FMI2_TYPES_H
#define BALLSCREW_FMI2_TYPES_H
#include <stddef.h>
typedef void *fmi2Component;
typedef void *fmi2ComponentEnvironment;
typedef void *fmi2FMUstate;
typedef unsigned int fmi2ValueReference;
typedef double fmi2Real;
typedef int fmi2Integer;
typedef int fmi2Boolean;
typedef char fmi2Char;
typedef const fmi2Char *fmi2String;
typedef char fmi2Byte;
#define fmi2True 1
#define fmi2False 0
#define fmi2TypesPlatform "default"
#define fmi2Version "2.0"
typedef enum { fmi2OK, fmi2Warning, fmi2Discard, fmi2Error, fmi2Fatal, fmi2Pending } fmi2Status;
typedef enum { fmi2ModelExchange, fmi2CoSimulation } fmi2Type;
typedef enum {
    fmi2DoStepStatus, fmi2PendingStatus, fmi2LastSuccessfulTime, fmi2Terminated
} fmi2StatusKind;
typedef struct {
    void (*logger)(fmi2ComponentEnvironment, fmi2String, fmi2Status, fmi2String, fmi2String, ...);
    void *(*allocateMemory)(size_t, size_t);
    void (*freeMemory)(void *);
    void (*stepFinished)(fmi2ComponentEnvironment, fmi2Status);
    fmi2ComponentEnvironment componentEnvironment;
} fmi2CallbackFunctions;
#endif
"""
"""What the compile of :func:`fmu_build` includes as ``fmi2Functions.h``."""


@dataclass(frozen=True)
class FmuBuild:
    """The FMU's bytes and how its binary came about.

    ``platform`` is the FMI platform folder of the binary (None: a source FMU only),
    ``compiler`` the compiler's first ``--version`` line and path, ``note`` one
    sentence for the user.
    """

    data: bytes
    platform: str | None
    compiler: str | None
    note: str


def fmi_platform() -> str | None:
    """The FMI 2.0 platform folder of this machine (``linux64``, ``darwin64``, ``win64``, ...)."""
    bits = struct.calcsize("P") * 8
    name: str = getattr(sys, "platform")  # noqa: B009 - a plain str, not narrowed per platform
    folders = {"linux": "linux", "darwin": "darwin", "win32": "win", "cygwin": "win"}
    for prefix, folder in folders.items():
        if name.startswith(prefix):
            return f"{folder}{bits}"
    return None


def find_compiler() -> str | None:
    """The C compiler to build with: ``$CC``, else the first of cc, gcc, clang on the PATH."""
    names = [os.environ["CC"]] if os.environ.get("CC") else ["cc", "gcc", "clang"]
    for name in names:
        found = shutil.which(name)
        if found:
            return found
    return None


def _compile(compiler: str, platform: str, sources: dict[str, bytes]) -> bytes:
    """The shared library of ``sources`` built by ``compiler`` for ``platform``."""
    with tempfile.TemporaryDirectory(prefix="ballscrew-fmu-") as folder:
        root = Path(folder)
        for name, data in {**sources, "fmi2Functions.h": FMI2_TYPES.encode()}.items():
            (root / name).write_bytes(data)
        out = root / _library_name(platform)
        shared = ["-dynamiclib"] if out.suffix == ".dylib" else ["-shared", "-fPIC"]
        command = [compiler, *shared, "-O2", "-std=c99", "-I", str(root), "-o", str(out),
                   str(root / "ballscrew_friction_fmu.c")]  # fmt: skip
        subprocess.run(command, capture_output=True, check=True, timeout=300)
        return out.read_bytes()


def _version_line(compiler: str) -> str:
    try:
        done = subprocess.run([compiler, "--version"], capture_output=True, text=True,
                              timeout=60, check=False)  # fmt: skip
    except OSError:
        return compiler
    first = (done.stdout or done.stderr).strip().splitlines()
    return f"{first[0]} ({compiler})" if first else compiler


def fmu_build(m: FrictionMap, version: str, header: bytes, *, binary: bool = True) -> FmuBuild:
    """The FMU of the map around its C ``header``, with this platform's binary if it builds.

    ``binary=False`` writes the source FMU alone. ``header`` is
    :func:`ballscrew.report.friction_files.c_header` of the map, handed in so that
    this module does not import the one that imports it.
    """
    digest = hashlib.sha256(header).hexdigest()
    guid = f"{{{digest[:8]}-{digest[8:12]}-{digest[12:16]}-{digest[16:20]}-{digest[20:32]}}}"
    source = _SOURCE.replace("@GUID@", guid).replace("@T0@", repr(float(m.temperatures[0])))
    sources = {"ballscrew_friction_map.h": header,
               "ballscrew_friction_fmu.c": source.encode()}  # fmt: skip
    platform, compiler = fmi_platform(), find_compiler() if binary else None
    library, used = None, None
    if not binary:
        note = "a source FMU (no binary asked for): the importer compiles sources/"
    elif platform is None or compiler is None:
        note = (
            "no C compiler found (set CC, or install cc, gcc or clang): a source FMU; "
            "compile it where it is used, e.g. with FMPy and CMake: fmpy compile FILE.fmu"
        )
        if platform is None:
            note = f"platform {sys.platform!r} has no FMI 2.0 binary folder: a source FMU"
    else:
        used = _version_line(compiler)
        try:
            library = _compile(compiler, platform, sources)
        except (OSError, subprocess.SubprocessError) as err:
            detail = getattr(err, "stderr", b"") or b""
            text = detail.decode("utf-8", "replace").strip().splitlines()
            note = (
                f"the compile with {used} failed ({text[0] if text else err}): a source "
                "FMU; compile it where it is used, e.g. with FMPy and CMake: fmpy compile FILE.fmu"
            )
            platform, used = None, None
        else:
            note = (
                f"binary for {platform} compiled with {used}; the sources are kept for "
                "other platforms"
            )
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w") as archive:
        _entry(archive, "modelDescription.xml", _model_description(m, version, guid).encode())
        for name, data in sources.items():
            _entry(archive, f"sources/{name}", data)
        if library is not None and platform is not None:
            _entry(archive, f"binaries/{platform}/{_library_name(platform)}", library)
    return FmuBuild(buffer.getvalue(), platform if library else None, used, note)


def _library_name(platform: str) -> str:
    """The shared library's file name on ``platform`` (FMI 2.0: the model identifier)."""
    suffix = {"darwin": ".dylib", "win": ".dll"}.get(platform.rstrip("0123456789"), ".so")
    return f"{MODEL_IDENTIFIER}{suffix}"


def fmu_bytes(m: FrictionMap, version: str, header: bytes) -> bytes:
    """The source FMU of the map (no binary) around its C ``header``, reproducibly."""
    return fmu_build(m, version, header, binary=False).data
