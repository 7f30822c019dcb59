-- SPDX-License-Identifier: MIT
-- The fleet table as one aggregate over every wheel row at read time (what `Store::fleet_table`
-- ran before schema version 3 kept per-wheel sums): bench/store_bench.sh times it on the same
-- store as the baseline of the fleet table's figure. The same text on SQLite and PostgreSQL.
WITH last_maintenance AS (SELECT wheel_id, MAX(at) AS at FROM maintenance_events
GROUP BY wheel_id),
per_run AS (SELECT w.wheel_id, w.started_at, w.odometer_km AS x, w.wear_mm AS y,
CASE WHEN m.at IS NULL OR w.started_at >= m.at THEN 1 ELSE 0 END AS since
FROM wheel_runs w LEFT JOIN last_maintenance m ON m.wheel_id = w.wheel_id),
fit AS (SELECT wheel_id, COUNT(*) AS runs, SUM(since) AS runs_since,
MAX(started_at) AS last_at, MAX(x) AS last_x,
SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN 1 ELSE 0 END) AS n,
SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN x ELSE 0 END) AS sx,
SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN y ELSE 0 END) AS sy,
SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN x * x ELSE 0 END) AS sxx,
SUM(CASE WHEN since = 1 AND y IS NOT NULL THEN x * y ELSE 0 END) AS sxy
FROM per_run GROUP BY wheel_id),
alarms AS (SELECT wheel_id, COUNT(*) AS events FROM alarm_events
WHERE wheel_id IS NOT NULL GROUP BY wheel_id)
SELECT l.name, h.axle, h.side, COALESCE(f.runs, 0), COALESCE(f.runs_since, 0),
COALESCE(f.last_at, ''), COALESCE(f.last_x, 0),
-- The latest run's wear: one index seek per wheel (wheel_runs_by_wheel).
(SELECT t.wear_mm FROM wheel_runs t WHERE t.wheel_id = h.id
ORDER BY t.started_at DESC, t.run_id DESC LIMIT 1),
COALESCE(f.n, 0), COALESCE(f.sx, 0), COALESCE(f.sy, 0), COALESCE(f.sxx, 0),
COALESCE(f.sxy, 0), COALESCE(m.at, ''), COALESCE(a.events, 0)
FROM wheels h JOIN locomotives l ON l.id = h.locomotive_id
LEFT JOIN fit f ON f.wheel_id = h.id
LEFT JOIN last_maintenance m ON m.wheel_id = h.id
LEFT JOIN alarms a ON a.wheel_id = h.id
ORDER BY l.name, h.axle, h.side;
