// The page's part-program section: sends the program to /api/program and shows the
// summary per axis (the command line's table). Every rule and message is the server's.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const ROWS = [
    ["energy supplied [J]", (a) => a.supplied_energy_J, 4],
    ["energy taken back [J]", (a) => a.regenerated_energy_J, 4],
    ["process work [J]", (a) => a.process_work_J, 4],
    ["screw friction [J]", (a) => a.friction_energy_J, 4],
    ["support bearings [J]", (a) => a.bearing_energy_J, 3],
    ["copper loss [J]", (a) => a.copper_loss_J ?? "-", 4],
    ["drive loss [J]", (a) => a.drive_loss_J ?? "-", 4],
    ["energy from the grid [J]", (a) => a.grid_energy_J ?? "-", 4],
    ["friction share", (a) => (a.friction_share === null ? "-" : (100 * a.friction_share).toFixed(1) + " %"), 0],
    ["peak motor torque [N·m]", (a) => a.peak_motor_torque_Nm, 3],
    ["RMS motor torque [N·m]", (a) => a.rms_motor_torque_Nm, 3],
    ["top temperature [°C]", (a) => a.max_temperature_C, 4],
    ["thermal lead error over the travel [µm]", (a) => a.thermal_lead_error_um, 2],
    ["reversals", (a) => a.reversals, 0],
    ["load before/after", (a) => Object.entries(a.load_directions).map(([k, n]) => n + " × " + k).join(", ") || "-", 0],
    ["lost motion [µm]", (a) => (a.lost_motion_um ? a.lost_motion_um.map((v) => v.toFixed(1)).join(" to ") : "-"), 0],
    // The axis check over the program: the worst verdict and the rows that are not OK.
    ["verdict", (a) => [a.verdict, ...a.criteria.filter((c) => c.verdict === "NOT OK" || c.verdict === "CHECK")
      .map((c) => c.name + " " + c.verdict)].join("; "), 0],
  ];

  function cell(row, text, header) {
    const c = document.createElement(header ? "th" : "td");
    c.textContent = text;
    row.appendChild(c);
  }

  function show(doc) {
    const table = $("program_table");
    table.replaceChildren();
    const letters = Object.keys(doc.axes);
    const head = table.insertRow();
    cell(head, "quantity", true);
    letters.forEach((k) => cell(head, k, true));
    for (const [label, get, digits] of ROWS) {
      const row = table.insertRow();
      row.dataset.quantity = label;
      cell(row, label, false);
      for (const k of letters) {
        const v = get(doc.axes[k]);
        cell(row, typeof v === "number" && digits ? Number(v.toPrecision(digits)).toString() : String(v), false);
      }
    }
    const totals = doc.machine_totals;
    $("program_status").textContent =
      doc.blocks + " blocks, " + doc.program_time_s.toFixed(2) + " s (nominal " +
      doc.nominal_time_s.toFixed(2) + " s); machine: " + totals.supplied_energy_J.toFixed(0) +
      " J supplied, " + totals.friction_energy_J.toFixed(0) + " J screw friction";
    const notes = $("program_notes");
    notes.replaceChildren();
    for (const text of doc.notes) {
      const li = document.createElement("li");
      li.textContent = text;
      notes.appendChild(li);
    }
  }

  async function runProgram() {
    $("program_status").textContent = "computing...";
    $("program_table").replaceChildren();
    let response;
    try {
      response = await fetch("/api/program", {
        method: "POST",
        headers: { "content-type": "application/json" },
        body: JSON.stringify({ program: $("program_text").value }),
      });
    } catch (err) {
      $("program_status").textContent = "the server did not answer";
      return;
    }
    const doc = await response.json();
    if (!response.ok) {
      $("program_status").textContent = "error: " + doc.error;
      return;
    }
    show(doc);
  }

  document.addEventListener("DOMContentLoaded", () => {
    $("program_run").addEventListener("click", runProgram);
  });
})();
