// The ballscrew calculator's page: builds a case from the form, asks the server
// (/api/evaluate) as inputs change, draws the results as SVG charts and offers
// the files. Every rule and message comes from the server, which reads the case
// as the command line does; this script only shows them beside the field.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const DEBOUNCE_MS = 120;
  const MODEL_COLORS = {
    complete: "#1f5fa8", catalog: "#333333", "harris-simplified": "#c0392b",
    olaru: "#2e8b57", viscoelastic: "#8e44ad", "harris-full": "#b9770e",
  };
  const PART_COLORS = ["#1f5fa8", "#e67e22", "#27ae60", "#8e44ad", "#c0392b", "#16a085",
    "#7f8c8d", "#d4ac0d"];
  const PART_NAMES = {
    rolling: "EHL rolling", sliding: "spin and sliding", hysteresis: "elastic hysteresis",
    four_point: "4-point spin", ball_ball: "ball-ball sliding", seals: "wipers",
    helix_slip: "helix slip across the groove", recirculation: "recirculation push",
    preload: "preload drag", load: "load term",
  };
  const PRELOAD_UNITS = {
    preload: [["kN", "2"], ["N"], ["lbf"]],
    preload_drag_torque: [["N*m", "0.4"], ["N*cm"], ["lbf*in"]],
    preload_share: [["%", "5"]],
  };
  const DIMENSION_QTYS = ["pitch_diameter", "lead", "ball_diameter", "contact_angle"];
  const DIMENSION_NUMBERS = ["conformity_screw", "conformity_nut", "loaded_turns", "circuits"];
  const OWN_OIL = ["nu40", "nu100", "density15"];
  // The case file's defaults where a file leaves a key out (ballscrew case --reference).
  const FILE_DEFAULTS = {
    speed: "10..3000:60 rpm", temperature: "20 degC", axial_load: "0 N", moving_mass: "0 kg",
  };

  const state = {
    base: {}, seq: 0, timer: 0, controller: null, result: null, changedAt: 0, revision: 0,
  };

  // ---------------------------------------------------------------- the request
  const text = (id) => $(id).value.trim();
  // A quantity as the case file writes it: the number as typed and the unit chosen, or
  // the text as typed when it carries its own unit ("1/4 in", "600 in/min", "200 lbf").
  // Nothing typed is sent as "" so that the server names the field, never a bare unit.
  const PLAIN_NUMBER = /^[-+0-9.eE\s\/]*$/;
  const qty = (id, unitId) => {
    const typed = text(id);
    if (typed === "") return "";
    if (!PLAIN_NUMBER.test(typed)) return typed;
    return `${typed} ${$(unitId || `${id}_unit`).value}`.trim();
  };
  const screwMode = () => document.querySelector('input[name="screw_mode"]:checked').value;
  const clone = (x) => JSON.parse(JSON.stringify(x || {}));
  const isTable = (v) => v !== null && typeof v === "object" && !Array.isArray(v);
  const unwrap = (v) => (isTable(v) && "value" in v ? v.value : v);
  const numberOrText = (v) => (v !== "" && Number.isFinite(Number(v)) ? Number(v) : v);

  function section(c, name) {
    if (!isTable(c[name])) c[name] = {};
    return c[name];
  }

  // Set a key, keeping the file's reason when a value marked as assumed is unchanged.
  function keep(table, key, value) {
    const old = table[key];
    if (isTable(old) && "assumed" in old && String(old.value) === String(value)) return;
    table[key] = value;
  }

  function speedText() {
    return `${text("speed_from")}..${text("speed_to")}:${text("speed_points")} ${$("speed_unit").value}`;
  }

  function buildCase() {
    const c = clone(state.base);
    c.title = text("title");
    const screw = section(c, "screw");
    if (screwMode() === "designation") {
      keep(screw, "designation", text("designation"));
    } else {
      delete screw.designation;
      for (const k of DIMENSION_QTYS) keep(screw, k, qty(k));
      for (const k of DIMENSION_NUMBERS) keep(screw, k, numberOrText(text(k)));
      keep(screw, "nut", $("nut").value);
    }
    const kind = $("preload_kind").value;
    for (const k of Object.keys(PRELOAD_UNITS)) if (k !== kind) delete screw[k];
    keep(screw, kind, qty("preload_value", "preload_unit"));
    if (kind === "preload_share" && text("dynamic_load_rating") !== "") {
      keep(screw, "dynamic_load_rating", qty("dynamic_load_rating"));
    } else {
      delete screw.dynamic_load_rating;
    }
    const lub = section(c, "lubricant");
    if ($("lubricant").value) {
      keep(lub, "name", $("lubricant").value);
      for (const k of OWN_OIL) delete lub[k];
    } else {
      keep(lub, "name", text("oil_name"));
      for (const k of OWN_OIL) keep(lub, k, qty(k));
    }
    const op = section(c, "operation");
    keep(op, "speed", speedText());
    keep(op, "temperature", qty("temperature"));
    keep(op, "axial_load", qty("axial_load"));
    if ($("move_on").checked) keep(section(c, "axis"), "moving_mass", qty("moving_mass"));
    return c;
  }

  function buildRequest() {
    const models = [...document.querySelectorAll('input[name="model"]:checked')].map((e) => e.value);
    const request = { case: buildCase(), models, units: $("units").value };
    if ($("move_on").checked) {
      request.move = { stroke: qty("stroke"), feed: qty("feed"), acceleration: qty("acceleration") };
    }
    return request;
  }

  // ---------------------------------------------------------------- asking the server
  function schedule(delay) {
    state.changedAt = performance.now();
    clearTimeout(state.timer);
    state.timer = setTimeout(compute, delay === undefined ? DEBOUNCE_MS : delay);
  }

  async function compute() {
    const seq = ++state.seq;
    if (state.controller) state.controller.abort();
    state.controller = new AbortController();
    $("status").textContent = "computing...";
    let response;
    let data;
    try {
      response = await fetch("/api/evaluate", {
        method: "POST",
        headers: { "content-type": "application/json" },
        body: JSON.stringify(buildRequest()),
        signal: state.controller.signal,
      });
      data = await response.json();
    } catch (err) {
      if (err.name === "AbortError") return;
      console.error(err);
      if (seq === state.seq) showGeneral("The server did not answer; is ballscrew serve still running?");
      return;
    }
    if (seq !== state.seq) return; // a newer request is on its way
    if (!response.ok) {
      showError(data.field || "", data.error || `refused (${response.status})`);
      return;
    }
    clearErrors();
    state.result = data;
    render(data);
    state.revision += 1;
    const took = performance.now() - state.changedAt;
    document.body.dataset.revision = String(state.revision);
    document.body.dataset.updateMs = took.toFixed(0);
    $("status").textContent =
      `${data.points} operating point${data.points === 1 ? "" : "s"} x ${data.models.length} ` +
      `models: computed in ${data.compute_ms.toFixed(0)} ms, shown ${took.toFixed(0)} ms after the last change`;
  }

  // ---------------------------------------------------------------- errors beside the field
  function fieldKey(field) {
    if (field === "designation") return "screw.designation";
    if (field === "lubricant") return "lubricant.name";
    if (field.startsWith("screw.preload")) return "screw.preload";
    if (field.startsWith("--move")) return `move.${field.slice(6).trim() || "stroke"}`;
    return field;
  }

  const visible = (el) => el.offsetParent !== null;

  function boxFor(field) {
    const find = (key) =>
      [...document.querySelectorAll("[data-field]")].find((el) => el.dataset.field === key && visible(el));
    const key = fieldKey(field);
    let box = find(key);
    // A value the form does not show: beside what gave it (the designation, the oil).
    if (!box && key.startsWith("screw.")) box = find("screw.designation");
    if (!box && key.startsWith("lubricant.")) box = find("lubricant.name");
    if (!box && key.startsWith("axis.")) box = find("axis.moving_mass");
    return box;
  }

  function clearErrors() {
    for (const el of document.querySelectorAll(".field.invalid")) {
      el.classList.remove("invalid");
      el.querySelector(".error").textContent = "";
    }
    $("general_error").hidden = true;
    $("results").classList.remove("stale");
  }

  function showError(field, message) {
    clearErrors();
    $("results").classList.add("stale");
    $("status").textContent = "The inputs have an error (marked beside the field); the results shown are the last good ones.";
    const box = boxFor(field);
    if (!box) {
      showGeneral(message);
      return;
    }
    box.classList.add("invalid");
    box.querySelector(".error").textContent = message;
  }

  function showGeneral(message) {
    $("general_error").textContent = message;
    $("general_error").hidden = false;
    $("results").classList.add("stale");
  }

  // ---------------------------------------------------------------- charts (SVG)
  const esc = (s) => String(s).replace(/[&<>"']/g, (ch) => `&#${ch.charCodeAt(0)};`);

  function fmt(v) {
    const a = Math.abs(v);
    if (a === 0) return "0";
    if (a >= 1e5 || a < 1e-3) return v.toExponential(1);
    return String(Number(v.toPrecision(4)));
  }

  function ticks(lo, hi, count) {
    if (!(hi > lo)) hi = lo + (Math.abs(lo) || 1);
    const raw = (hi - lo) / count;
    const mag = 10 ** Math.floor(Math.log10(raw));
    const step = [1, 2, 2.5, 5, 10].map((f) => f * mag).find((s) => (hi - lo) / s <= count) || 10 * mag;
    const out = [];
    for (let v = Math.ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step) {
      out.push(Math.abs(v) < step * 1e-9 ? 0 : v);
    }
    return { values: out, lo: Math.min(lo, out[0]), hi: Math.max(hi, out[out.length - 1]) };
  }

  // series: [{name, color, dash, x, y}]; stacked draws the y's on top of each other as areas.
  function drawChart(id, series, xLabel, yLabel, stacked) {
    const svg = $(id);
    const width = Math.max(260, Math.floor(svg.parentElement.clientWidth));
    const height = Math.round(Math.max(200, Math.min(320, width * 0.58)));
    const m = { l: 60, r: 14, t: 10, b: 42 };
    const xs = series.flatMap((s) => s.x).filter(Number.isFinite);
    const tops = [];
    if (stacked) {
      const sums = series.length ? series[0].x.map(() => 0) : [];
      for (const s of series) {
        s.base = sums.slice();
        s.y.forEach((v, i) => { sums[i] += Number.isFinite(v) ? v : 0; });
        s.top = sums.slice();
      }
      tops.push(...sums);
    } else {
      tops.push(...series.flatMap((s) => s.y).filter(Number.isFinite));
    }
    const xt = ticks(xs.length ? Math.min(...xs) : 0, xs.length ? Math.max(...xs) : 1, width < 420 ? 4 : 7);
    const yt = ticks(0, tops.length ? Math.max(...tops) * 1.05 : 1, 5);
    const px = (x) => m.l + ((x - xt.lo) / (xt.hi - xt.lo)) * (width - m.l - m.r);
    const py = (y) => height - m.b - ((y - yt.lo) / (yt.hi - yt.lo)) * (height - m.t - m.b);
    const parts = [];
    for (const v of yt.values) {
      parts.push(`<line class="grid" x1="${m.l}" x2="${width - m.r}" y1="${py(v)}" y2="${py(v)}"/>`);
      parts.push(`<text class="tick" x="${m.l - 6}" y="${py(v) + 4}" text-anchor="end">${fmt(v)}</text>`);
    }
    for (const v of xt.values) {
      parts.push(`<line class="grid" y1="${m.t}" y2="${height - m.b}" x1="${px(v)}" x2="${px(v)}"/>`);
      parts.push(`<text class="tick" x="${px(v)}" y="${height - m.b + 16}" text-anchor="middle">${fmt(v)}</text>`);
    }
    parts.push(`<rect class="frame" x="${m.l}" y="${m.t}" width="${width - m.l - m.r}" height="${height - m.t - m.b}"/>`);
    for (const s of series) {
      const pts = s.x.map((x, i) => [x, stacked ? s.top[i] : s.y[i]]).filter((p) => Number.isFinite(p[0]) && Number.isFinite(p[1]));
      if (!pts.length) continue;
      const line = pts.map((p) => `${px(p[0]).toFixed(1)},${py(p[1]).toFixed(1)}`).join(" ");
      if (stacked) {
        const under = s.x.map((x, i) => `${px(x).toFixed(1)},${py(s.base[i]).toFixed(1)}`).reverse().join(" ");
        parts.push(`<polygon class="area" data-series="${esc(s.name)}" points="${line} ${under}" fill="${s.color}" fill-opacity="0.75" stroke="${s.color}"/>`);
      } else if (pts.length === 1) {
        parts.push(`<circle data-series="${esc(s.name)}" cx="${px(pts[0][0])}" cy="${py(pts[0][1])}" r="4" fill="${s.color}"/>`);
      } else {
        parts.push(`<polyline class="curve" data-series="${esc(s.name)}" points="${line}" fill="none" stroke="${s.color}" stroke-width="2"${s.dash ? ' stroke-dasharray="7 5"' : ""}/>`);
      }
    }
    parts.push(`<text class="label" x="${(m.l + width - m.r) / 2}" y="${height - 6}" text-anchor="middle">${esc(xLabel)}</text>`);
    parts.push(`<text class="label" transform="translate(14 ${(m.t + height - m.b) / 2}) rotate(-90)" text-anchor="middle">${esc(yLabel)}</text>`);
    svg.setAttribute("viewBox", `0 0 ${width} ${height}`);
    svg.setAttribute("width", String(width));
    svg.setAttribute("height", String(height));
    svg.innerHTML = parts.join("");
    const legend = $(id.replace("chart_", "legend_"));
    legend.innerHTML = series.map((s) =>
      `<span class="key"><svg width="26" height="10" aria-hidden="true">${stacked
        ? `<rect width="26" height="10" fill="${s.color}" fill-opacity="0.75"/>`
        : `<line x1="0" x2="26" y1="5" y2="5" stroke="${s.color}" stroke-width="2"${s.dash ? ' stroke-dasharray="7 5"' : ""}/>`}</svg>${esc(s.name)}</span>`).join("");
  }

  // ---------------------------------------------------------------- results
  // The figures shown come converted from the server (data.display: the command line's
  // --units); efficiencies, speeds, powers and energies are the same in every system.
  function curveName(curve, i, data) {
    const shown = data.display.curves;
    const u = data.display.units;
    const temps = new Set(data.curves.map((c) => c.temperature_C));
    const loads = new Set(data.curves.map((c) => c.axial_load_N));
    let name = curve.model === "catalog" ? "catalog (reference)" : curve.model;
    if (temps.size > 1) name += `, ${fmt(shown[i].temperature)} ${u.temperature}`;
    if (loads.size > 1) name += `, ${fmt(shown[i].axial_load)} ${u.force}`;
    return name;
  }

  function render(data) {
    const d = data.display;
    const u = d.units;
    const lines = (get) => data.curves.map((c, i) => ({
      name: curveName(c, i, data), color: MODEL_COLORS[c.model] || "#555", dash: c.model === "catalog",
      x: c.speed_rpm, y: get(c, i),
    }));
    document.body.dataset.units = d.system;
    drawChart("chart_torque", lines((c, i) => d.curves[i].torque), "screw speed [rpm]", `friction torque [${u.torque}]`);
    drawChart("chart_efficiency", lines((c) => c.efficiency).map((s) => ({ ...s, y: s.y.map((v) => (v === null ? null : 100 * v)) })),
      "screw speed [rpm]", "efficiency [%]");
    drawChart("chart_power", lines((c) => c.power_W), "screw speed [rpm]", "power loss [W]");
    renderBudget(data.budget, d);
    const s = data.screw;
    const ds = d.screw;
    $("summary").textContent =
      `${data.title}: ball centre diameter ${fmt(ds.pitch_diameter)} ${u.length}, lead ${fmt(ds.lead)} ${u.length}, ` +
      `balls ${fmt(ds.ball_diameter)} ${u.length} at ${fmt(s.contact_angle_deg)}°, ${s.nut} nut, preload ` +
      `${fmt(ds.preload)} ${u.force}, ${s.loaded_balls} loaded balls per nut; ${s.lubricant}.` +
      (s.source ? ` Source: ${s.source}.` : "") +
      (s.assumptions.length ? ` Assumed: ${s.assumptions.join("; ")}.` : "");
    const warnings = [
      ...data.warnings,
      ...(data.energy ? data.energy.warnings.map((w) => `warning: ${w}`) : []),
      ...(data.energy ? data.energy.notes.map((n) => `note: ${n}`) : []),
    ];
    $("warnings").innerHTML = warnings.length
      ? warnings.map((w) => `<li class="${w.startsWith("warning") ? "warn" : "note"}">${esc(w)}</li>`).join("")
      : "<li>Every input is inside the validity ranges of the models and correlations used.</li>";
    renderEnergy(data.energy, d);
    $("commands").textContent = [
      "# save the case file (button above) as case.toml, then",
      data.command,
      ...(data.energy ? [data.energy.command] : []),
      ...(data.energy && data.energy.check ? [data.energy.check.command] : []),
    ].join("\n");
    for (const id of ["download_csv", "download_toml", "download_meta"]) $(id).disabled = false;
  }

  function renderBudget(budget, d) {
    if (!budget) {
      $("budget_figure").hidden = true;
      return;
    }
    $("budget_figure").hidden = false;
    const u = d.units;
    const parts = d.budget.components;
    $("budget_caption").textContent =
      `Loss budget of the ${budget.model} model at ${fmt(d.budget.temperature)} ${u.temperature} and ${fmt(d.budget.axial_load)} ${u.force}`;
    const names = Object.keys(parts).filter((k) => parts[k].some((v) => v > 0));
    const series = names.map((k, i) => ({
      name: PART_NAMES[k] || k, color: PART_COLORS[i % PART_COLORS.length], x: budget.speed_rpm, y: parts[k],
    }));
    drawChart("chart_budget", series, "screw speed [rpm]", `torque [${u.torque}]`, true);
    const n = budget.speed_rpm.length;
    const at = [...new Set([0, Math.floor((n - 1) / 2), n - 1])];
    const total = at.map((i) => names.reduce((sum, k) => sum + (parts[k][i] || 0), 0));
    const head = `<tr><th>mechanism</th>${at.map((i) => `<th>${fmt(budget.speed_rpm[i])} rpm</th>`).join("")}</tr>`;
    const rows = names.map((k) => `<tr><td>${esc(PART_NAMES[k] || k)}</td>${at.map((i, j) => {
      const v = parts[k][i] || 0;
      return `<td>${fmt(v)} ${esc(u.torque)} <span class="share">${total[j] > 0 ? ((100 * v) / total[j]).toFixed(0) : 0} %</span></td>`;
    }).join("")}</tr>`);
    const sum = `<tr class="total"><td>total</td>${total.map((v) => `<td>${fmt(v)} ${esc(u.torque)}</td>`).join("")}</tr>`;
    $("budget_table").innerHTML = `<thead>${head}</thead><tbody>${rows.join("")}${sum}</tbody>`;
  }

  function renderEnergy(e, d) {
    $("energy_section").hidden = !e;
    if (!e) return;
    const u = d.units;
    const de = d.energy;
    const eff = (v) => {
      if (v === null) return "none (no axial load)";
      return v <= 0 ? `${fmt(100 * v)} % (the load cannot back-drive the screw at this load)` : `${fmt(100 * v)} %`;
    };
    const rows = [
      ["move", `${e.move}, out and back at ${fmt(de.temperature)} ${u.temperature}`],
      ["duration", `${fmt(e.duration_s)} s`],
      ["friction energy of the screw", `${fmt(e.friction_energy_J)} J (out ${fmt(e.friction_energy_out_J)} J, back ${fmt(e.friction_energy_back_J)} J)`],
      ["the same by the catalogue rule", `${fmt(e.constant_efficiency_energy_J)} J`],
      ["support bearings", `${fmt(e.bearing_energy_J)} J`],
      ["work on the load", `${fmt(e.load_work_J)} J`],
      ["peak motor torque", `${fmt(de.peak_motor_torque)} ${u.torque}`],
      ["RMS motor torque", `${fmt(de.rms_motor_torque)} ${u.torque}`],
      ["efficiency at the working point", `${eff(e.forward_efficiency)} forward, ${eff(e.reverse_efficiency)} back-driving`],
    ];
    $("energy_table").innerHTML = rows.map(([k, v]) => `<tr><th>${esc(k)}</th><td>${esc(v)}</td></tr>`).join("");
    renderCheck(e.check, d.check);
  }

  // The axis check of the same move: one row per criterion, as `ballscrew check` prints it.
  // Each row's name, value, limit and unit as shown (d: data.display.check, same order).
  function renderCheck(c, d) {
    $("check_section").hidden = !c;
    if (!c) return;
    const num = (v) => (v === null || v === undefined ? "-" : fmt(v));
    if (c.error) {
      $("check_verdict").textContent = `not checked: ${c.error}`;
      $("check_table").innerHTML = "";
      return;
    }
    const missing = c.not_checked.length ? `, ${c.not_checked.length} not checked` : "";
    $("check_verdict").textContent = `verdict: ${c.verdict}${missing}`;
    const head = "<thead><tr><th>criterion</th><th>value</th><th>limit</th><th>unit</th><th>use</th><th>use, 95 %</th><th>verdict</th><th>P(NOT OK)</th><th>95 % confidence</th><th>what to change</th></tr></thead>";
    const pct = (v) => `${Math.round(100 * v)} %`;
    const rows = c.criteria.map((r, i) => {
      const shown = d[i];
      const use = r.utilisation === null ? "-" : pct(r.utilisation);
      const spread = r.utilisation_95 ? `${pct(r.utilisation_95[0])} to ${pct(r.utilisation_95[1])}` : "-";
      const p = r.p_not_ok === null || r.p_not_ok === undefined ? "-" : pct(r.p_not_ok);
      return `<tr class="verdict" data-key="${esc(r.key)}" data-verdict="${esc(r.verdict)}"><th title="${esc(r.source)}">${esc(shown.name)}</th><td>${num(shown.value)}</td><td>${num(shown.limit)}</td><td>${esc(shown.unit)}</td><td>${use}</td><td>${spread}</td><td>${esc(r.verdict)}</td><td>${p}</td><td>${esc(r.guarded_verdict ?? "-")}</td><td>${esc(r.advice)}</td></tr>`;
    });
    const assumed = c.assumptions.map((a) => `<tr><td colspan="10" class="assumed">assumed: ${esc(a)}</td></tr>`);
    $("check_table").innerHTML = `${head}<tbody>${rows.join("")}${assumed.join("")}</tbody>`;
  }

  // ---------------------------------------------------------------- filling the form from a file
  // A unit the list lacks is added; a value the file gives without a unit gets
  // "(no unit)", so the server's message asks for one: the page never adds a unit.
  function setUnit(id, unit) {
    const select = $(id);
    if (![...select.options].some((o) => o.value === unit)) select.add(new Option(unit || "(no unit)", unit));
    select.value = unit;
  }

  // "32 mm" -> ["32", "mm"]; lists and ranges take their first value.
  function splitQty(value) {
    const v = String(unwrap(value) ?? "").trim();
    const m = v.match(/^([-+0-9.eE]+)\s*(?:(?:,|\.\.)[^a-zA-Z%]*)?(.*)$/);
    return m ? [m[1], m[2].replace(/:\s*\d+\s*$/, "").trim()] : [v, ""];
  }

  function setQty(id, value, unitId) {
    const [number, unit] = splitQty(value);
    $(id).value = number;
    setUnit(unitId || `${id}_unit`, unit);
  }

  function setSpeed(value, notes) {
    const v = String(unwrap(value)).trim();
    const range = v.match(/^([-+0-9.eE]+)\s*\.\.\s*([-+0-9.eE]+)\s*(?::\s*(\d+))?\s*(.*?)\s*(?::\s*(\d+))?$/);
    if (range) {
      $("speed_from").value = range[1];
      $("speed_to").value = range[2];
      $("speed_points").value = range[3] || range[5] || "50";
      setUnit("speed_unit", range[4] || "");
      return;
    }
    const list = v.split(",").map((p) => p.trim());
    const [first] = splitQty(list[0]);
    const [last, unit] = splitQty(list[list.length - 1]);
    $("speed_from").value = first;
    $("speed_to").value = last;
    $("speed_points").value = String(list.length);
    setUnit("speed_unit", unit);
    if (list.length > 2) notes.push(`the speeds ${v} became ${list.length} evenly spaced speeds`);
  }

  function setPreloadKind(kind, keepValue) {
    $("preload_kind").value = kind;
    const select = $("preload_unit");
    select.innerHTML = "";
    for (const [unit] of PRELOAD_UNITS[kind]) select.add(new Option(unit, unit));
    if (!keepValue) $("preload_value").value = PRELOAD_UNITS[kind][0][1];
    $("rating_field").hidden = kind !== "preload_share";
  }

  function setMode(mode) {
    document.querySelector(`input[name="screw_mode"][value="${mode}"]`).checked = true;
    $("by_designation").hidden = mode !== "designation";
    $("by_dimensions").hidden = mode !== "dimensions";
  }

  function fill(fields) {
    state.base = clone(fields);
    const notes = [];
    $("title").value = fields.title ?? "ball screw case";
    const screw = isTable(fields.screw) ? fields.screw : {};
    if (screw.designation !== undefined) {
      setMode("designation");
      $("designation").value = unwrap(screw.designation);
    } else {
      setMode("dimensions");
      for (const k of DIMENSION_QTYS) if (screw[k] !== undefined) setQty(k, screw[k]);
      for (const k of DIMENSION_NUMBERS) if (screw[k] !== undefined) $(k).value = String(unwrap(screw[k]));
      if (screw.nut !== undefined) $("nut").value = unwrap(screw.nut);
    }
    const kind = Object.keys(PRELOAD_UNITS).find((k) => screw[k] !== undefined) || "preload";
    setPreloadKind(kind, false);
    if (screw[kind] !== undefined) setQty("preload_value", screw[kind], "preload_unit");
    $("dynamic_load_rating").value = "";
    if (screw.dynamic_load_rating !== undefined) setQty("dynamic_load_rating", screw.dynamic_load_rating);
    const lub = isTable(fields.lubricant) ? fields.lubricant : {};
    const name = String(unwrap(lub.name) ?? "");
    const bundled = [...$("lubricant").options].some((o) => o.value && o.value.toLowerCase() === name.toLowerCase());
    const own = OWN_OIL.some((k) => lub[k] !== undefined);
    if (bundled && !own) {
      $("lubricant").value = [...$("lubricant").options].find((o) => o.value.toLowerCase() === name.toLowerCase()).value;
    } else {
      $("lubricant").value = "";
      $("oil_name").value = name;
      for (const k of OWN_OIL) if (lub[k] !== undefined) setQty(k, lub[k]);
    }
    const op = isTable(fields.operation) ? fields.operation : {};
    setSpeed(op.speed ?? FILE_DEFAULTS.speed, notes);
    for (const k of ["temperature", "axial_load"]) {
      const v = String(unwrap(op[k] ?? FILE_DEFAULTS[k]));
      if (/,|\.\./.test(v)) notes.push(`the page computes one ${k.replace("_", " ")}: the first of ${v}`);
      setQty(k, v);
    }
    const output = isTable(fields.output) ? fields.output : {};
    const system = String(unwrap(output.units) ?? "").toLowerCase();
    if ([...$("units").options].some((o) => o.value === system)) {
      $("units").value = system; // the file's [output] units, as the command line takes it
      keepUnitsInAddress();
    }
    const axis = isTable(fields.axis) ? fields.axis : {};
    setQty("moving_mass", axis.moving_mass ?? FILE_DEFAULTS.moving_mass);
    const formKeys = ["designation", ...Object.keys(PRELOAD_UNITS), "dynamic_load_rating",
      ...(screw.designation === undefined ? [...DIMENSION_QTYS, ...DIMENSION_NUMBERS, "nut"] : [])];
    const kept = [
      ...Object.keys(screw).filter((k) => !formKeys.includes(k)).map((k) => `screw.${k}`),
      ...Object.keys(lub).filter((k) => k !== "name" && !OWN_OIL.includes(k)).map((k) => `lubricant.${k}`),
      ...Object.keys(axis).filter((k) => k !== "moving_mass").map((k) => `axis.${k}`),
      ...Object.keys(fields).filter((k) => ["study", "description"].includes(k)),
    ];
    if (kept.length) notes.push(`kept as the file gives them (not on the form): ${kept.join(", ")}`);
    $("upload_notice").textContent = notes.length ? `Opened. Note: ${notes.join("; ")}.` : "Opened.";
    $("upload_notice").hidden = false;
    syncVisibility();
  }

  async function upload() {
    const file = $("upload").files[0];
    if (!file) return;
    const limit = Number($("inputs").dataset.maxBytes);
    if (file.size > limit) {
      showError("case", `case = '${file.name}' is not allowed: a case file under ${limit} bytes`);
      return;
    }
    const body = await file.text();
    const response = await fetch("/api/case", {
      method: "POST", headers: { "content-type": "application/toml" }, body,
    });
    const data = await response.json();
    $("upload").value = "";
    if (!response.ok) {
      showError(data.field || "case", data.error);
      return;
    }
    fill(data.fields);
    schedule(0);
  }

  // ---------------------------------------------------------------- files
  function slug(title) {
    return (title || "ballscrew").toLowerCase().replace(/[^a-z0-9]+/g, "-").replace(/^-|-$/g, "").slice(0, 60) || "ballscrew";
  }

  function download(name, content, type) {
    const url = URL.createObjectURL(new Blob([content], { type }));
    const a = document.createElement("a");
    a.href = url;
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 10000);
  }

  // ---------------------------------------------------------------- the page's address
  // The unit system shown is kept in the address (?units=imperial), to bookmark or share.
  function keepUnitsInAddress() {
    const url = new URL(window.location.href);
    if ($("units").value === "si") url.searchParams.delete("units");
    else url.searchParams.set("units", $("units").value);
    window.history.replaceState(null, "", url);
  }

  // ---------------------------------------------------------------- wiring
  function syncVisibility() {
    setMode(screwMode());
    $("own_oil").hidden = $("lubricant").value !== "";
    $("move_fields").hidden = !$("move_on").checked;
    $("rating_field").hidden = $("preload_kind").value !== "preload_share";
  }

  // ---------------------------------------------------------------- circular test, on demand
  async function runContour() {
    if (!state.result) return;
    $("contour_summary").textContent = "computing...";
    const body = { case: buildRequest().case, radius: $("contour_radius").value, feed: $("contour_feed").value };
    const response = await fetch("/api/contour", {
      method: "POST", headers: { "content-type": "application/json" }, body: JSON.stringify(body),
    });
    const data = await response.json();
    if (!response.ok) {
      $("contour_summary").textContent = data.error || `refused (${response.status})`;
      return;
    }
    const [plain, comp] = data.runs;
    $("contour_summary").textContent =
      `G ${fmt(plain.circular_deviation_G_um)} µm, glitch ${fmt(plain.largest_glitch_um)} µm; ` +
      `with compensation ${fmt(comp.circular_deviation_G_um)} µm, ${fmt(comp.largest_glitch_um)} µm`;
    drawPolar("chart_contour", data.runs);
  }

  // The deviation magnified about the nominal circle, as a ballbar's polar plot.
  function drawPolar(id, runs) {
    const svg = $(id);
    const size = Math.min(360, Math.max(240, Math.floor(svg.parentElement.clientWidth)));
    const c = size / 2;
    const devs = runs.flatMap((r) => r.radial_deviation.deviation_um);
    const lo = Math.min(...devs);
    const hi = Math.max(...devs);
    const span = Math.max(hi - lo, 1e-3);
    const r0 = c * 0.25;
    const scale = (c * 0.9 - r0) / span;
    const rad = (d) => r0 + (d - lo) * scale;
    const parts = [`<circle class="grid" cx="${c}" cy="${c}" r="${rad(0)}" fill="none" stroke="#999"/>`];
    runs.forEach((run, k) => {
      const a = run.radial_deviation.angle_deg;
      const d = run.radial_deviation.deviation_um;
      const pts = a.map((t, i) => {
        const th = (t * Math.PI) / 180;
        return `${(c + rad(d[i]) * Math.cos(th)).toFixed(1)},${(c - rad(d[i]) * Math.sin(th)).toFixed(1)}`;
      }).join(" ");
      parts.push(`<polygon class="curve" points="${pts}" fill="none" stroke="${k ? "#d62728" : "#1f77b4"}"` +
        ` stroke-width="1.5"${run.compensated ? ' stroke-dasharray="6 4"' : ""}/>`);
    });
    parts.push(`<text class="tick" x="4" y="${size - 6}">${fmt(lo)} to ${fmt(hi)} µm; grey: nominal; dashed: compensated</text>`);
    svg.setAttribute("viewBox", `0 0 ${size} ${size}`);
    svg.setAttribute("width", String(size));
    svg.setAttribute("height", String(size));
    svg.innerHTML = parts.join("");
  }


  // ---------------------------------------------------------------- choose a screw, on demand
  const SELECT_COLUMNS = [
    ["energy [J]", "energy_J", 4], ["L10 [h]", "L10_h", 3], ["stiffness [N/µm]", "stiffness_N_per_um", 3],
    ["lost motion [µm]", "lost_motion_um", 3], ["thermal error [µm]", "thermal_error_um", 3],
  ];

  function selectRow(table, r, label) {
    const row = table.insertRow();
    row.dataset.candidate = r.name;
    const name = row.insertCell();
    name.textContent = r.name + (r.estimated ? " (estimated ratings)" : "");
    row.insertCell().textContent = label;
    for (const [, key, digits] of SELECT_COLUMNS) {
      row.insertCell().textContent = r[key] === null ? "-" : Number(r[key].toPrecision(digits)).toString();
    }
    row.insertCell().textContent = r.binding;
  }

  async function runSelect() {
    const table = $("select_table");
    const request = buildRequest();
    if (!request.move) {
      $("select_summary").textContent = "tick the move above: the candidates are checked on it";
      return;
    }
    const checked = (name) => [...document.querySelectorAll(`input[name="${name}"]:checked`)].map((e) => e.value);
    const body = {
      case: request.case, move: request.move, diameter: $("select_diameter").value,
      lead: $("select_lead").value, makers: $("select_maker").value ? [$("select_maker").value] : [],
      preloads: checked("select_preload"), objectives: checked("select_objective"),
      sources: $("select_iso").checked ? ["catalogue", "iso"] : ["catalogue"],
    };
    $("select_summary").textContent = "computing...";
    $("select_reason").textContent = "";
    table.replaceChildren();
    const response = await fetch("/api/select", {
      method: "POST", headers: { "content-type": "application/json" }, body: JSON.stringify(body),
    });
    const data = await response.json();
    if (!response.ok) {
      $("select_summary").textContent = data.error || `refused (${response.status})`;
      return;
    }
    $("select_summary").textContent =
      `${data.candidates} candidates, ${data.feasible} feasible, ${data.front_size} on the front ` +
      `over ${data.objectives.join(", ")}`;
    $("select_reason").textContent = `Recommended: ${data.recommended.name}. Why: ${data.reason}.` +
      (data.rating_estimates ? ` ISO sizes: ${data.rating_estimates}.` : "");
    const head = table.insertRow();
    for (const h of ["candidate", "", ...SELECT_COLUMNS.map((c) => c[0]), "largest utilisation"]) {
      const th = document.createElement("th");
      th.textContent = h;
      head.appendChild(th);
    }
    if (!data.recommended.on_front) selectRow(table, data.recommended, "recommended");
    data.front.forEach((r) => selectRow(table, r, r.name === data.recommended.name ? "recommended" : "front"));
    data.rejected.forEach((r) => selectRow(table, r, "rejected"));
  }

  function start() {
    $("contour_run").addEventListener("click", runContour);
    $("select_run").addEventListener("click", runSelect);
    $("inputs").addEventListener("input", (ev) => {
      if (ev.target.id !== "upload") schedule();
    });
    $("inputs").addEventListener("change", (ev) => {
      if (ev.target.id === "upload") {
        upload();
        return;
      }
      if (ev.target.id === "preload_kind") setPreloadKind(ev.target.value, false);
      if (ev.target.id === "units") keepUnitsInAddress();
      syncVisibility();
      schedule();
    });
    $("inputs").addEventListener("submit", (ev) => ev.preventDefault());
    $("download_csv").addEventListener("click", () =>
      download(`${slug(state.result.title)}.csv`, state.result.csv, "text/csv"));
    $("download_toml").addEventListener("click", () =>
      download(`${slug(state.result.title)}.toml`, state.result.case_toml, "application/toml"));
    $("download_meta").addEventListener("click", () =>
      download(`${slug(state.result.title)}.csv.meta.json`, state.result.provenance, "application/json"));
    let resizeTimer = 0;
    window.addEventListener("resize", () => {
      clearTimeout(resizeTimer);
      resizeTimer = setTimeout(() => state.result && render(state.result), 150);
    });
    syncVisibility();
    schedule(0);
  }

  document.addEventListener("DOMContentLoaded", start);
})();
