using System.Globalization;
using System.Numerics;
using AcDream.Core.Dat;
using AcDream.Core.Physics;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>--accuracy</c>: how far each configuration is from the most accurate one, over thousands of
/// seeded random cases. Prints Markdown; every figure is recomputed from <c>new Random(5)</c>.
/// </summary>
internal static class AccuracyReport
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    public static void Run(TextWriter o)
    {
        o.WriteLine("# Accuracy report (seed 5)");
        o.WriteLine();
        Terrain(o);
        Floors(o);
        Course(o);
        Slopes(o);
        DoorsOnly(o);
        BodyAccuracy.Run(o);
        ObjectAccuracy.Run(o);
        VerticalAccuracy.Run(o);
        MoverAccuracy.Run(o);
        CastAccuracy.Run(o);
    }

    private static string F(double v, string format = "0.###") => v.ToString(format, Inv);

    private static string E(double v) => v.ToString("0.00e+0", Inv);

    // ---------------------------------------------------------------- terrain

    private static void Terrain(TextWriter o)
    {
        const int Landblocks = 400, Points = 25;
        o.WriteLine($"## Terrain Z: bilinear vs the game's triangles ({Landblocks} landblocks × {Points} points per height kind)");
        o.WriteLine();
        o.WriteLine("| heights | max \\|bilinear − triangles\\| (m) | mean (m) | max \\|engine triangles − double reference\\| (m) |");
        o.WriteLine("| --- | ---: | ---: | ---: |");
        var random = new Random(5);
        float[] table = World.NonLinearTable();
        foreach ((string name, Func<byte[]> heights) in new (string, Func<byte[]>)[]
        {
            ("rolling (index 60 ± 6, non-linear table)", () => World.RollingHeights(random, 60, 6)),
            ("random bytes (adversarial)", () => { var h = new byte[81]; random.NextBytes(h); return h; }),
        })
        {
            double max = 0, sum = 0, refMax = 0;
            int n = 0;
            for (int l = 0; l < Landblocks; l++)
            {
                uint id = World.LandblockId(random.Next(255), random.Next(255));
                byte[] h = heights();
                var bilinear = new TerrainSurface(h, table);
                var triangles = new TerrainSurface(h, table, id);
                var reference = new ReferenceTerrain(h, table, id);
                for (int p = 0; p < Points; p++)
                {
                    float x = random.NextSingle() * 192f, y = random.NextSingle() * 192f;
                    double t = triangles.SampleZ(x, y);
                    double e = Math.Abs(bilinear.SampleZ(x, y) - t);
                    max = Math.Max(max, e);
                    sum += e;
                    n++;
                    refMax = Math.Max(refMax, Math.Abs(t - reference.Sample(x, y).Z));
                }
            }

            o.WriteLine($"| {name} | {F(max, "0.00")} | {F(sum / n, "0.00")} | {E(refMax)} |");
        }

        o.WriteLine();
    }

    // ---------------------------------------------------------------- floors

    private static void Floors(TextWriter o)
    {
        const int Cells = 2000, Points = 20, EdgePoints = 10;
        const double NearEdge = 1e-3;
        var random = new Random(5);
        double max = 0, sum = 0, nearMax = 0;
        int both = 0, near = 0, refOnly = 0, floatOnly = 0, edgeMisses = 0, edgeTotal = 0;
        double worstRefOnlyEdge = 0, worstFloatOnlyEdge = 0;
        for (int c = 0; c < Cells; c++)
        {
            // A cell somewhere in its landblock, turned by a random yaw (and, for a third, tilted up to 8°),
            // its stored quaternion slightly non-unit, with 1..6 random convex sloped floor polygons.
            var origin = new Vector3(random.NextSingle() * 192f, random.NextSingle() * 192f, random.NextSingle() * 200f);
            Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, random.NextSingle() * 2 * MathF.PI);
            if (c % 3 == 0)
            {
                Vector3 axis = Vector3.Normalize(new Vector3(random.NextSingle() - 0.5f, random.NextSingle() - 0.5f, 0f));
                q = Quaternion.Concatenate(Quaternion.CreateFromAxisAngle(axis, random.NextSingle() * 0.14f), q);
            }

            float scale = 1f + ((random.NextSingle() - 0.5f) * 0.002f);
            var stored = new Quaternion(q.X * scale, q.Y * scale, q.Z * scale, q.W * scale);
            var builder = new CellBuilder(0xA9B40100u, origin, stored);
            var polygons = new List<Vector3[]>();
            int count = random.Next(1, 7);
            for (int p = 0; p < count; p++)
            {
                Vector3[] polygon = RandomFloorPolygon(random);
                polygons.Add(polygon);
                builder.Physics(polygon);
            }

            CellSurface cell = builder.Build();
            var reference = new ReferenceFloor(polygons, origin, stored);
            for (int i = 0; i < Points; i++)
            {
                double x = reference.MinX + (random.NextDouble() * (reference.MaxX - reference.MinX));
                double y = reference.MinY + (random.NextDouble() * (reference.MaxY - reference.MinY));
                float fx = (float)x, fy = (float)y;
                float? got = cell.SampleFloorZ(fx, fy);
                double? want = reference.TopZ(fx, fy, out double edgeDistance);
                if (got is float g && want is double w && edgeDistance > NearEdge)
                {
                    both++;
                    double e = Math.Abs(g - w);
                    max = Math.Max(max, e);
                    sum += e;
                }
                else if (got is float g2 && want is double w2)
                {
                    // Within 1 mm of an edge a stacked floor may be in for one and out for the other.
                    near++;
                    nearMax = Math.Max(nearMax, Math.Abs(g2 - w2));
                }
                else if (want is not null)
                {
                    refOnly++;
                    worstRefOnlyEdge = Math.Max(worstRefOnlyEdge, edgeDistance);
                }
                else if (got is not null)
                {
                    floatOnly++;
                    worstFloatOnlyEdge = Math.Max(worstFloatOnlyEdge, edgeDistance);
                }
            }

            for (int i = 0; i < EdgePoints; i++)
            {
                // A point on an edge or vertex of a fan triangle (rounded to float): the game's tolerance must find a floor.
                (double x, double y) = reference.RandomEdgePoint(random);
                edgeTotal++;
                if (cell.SampleFloorZ((float)x, (float)y) is null)
                {
                    edgeMisses++;
                }
            }
        }

        o.WriteLine($"## Floors: float `CellSurface.SampleFloorZ` vs a double-precision reference ({Cells} random cells × {Points} points, + {Cells * EdgePoints} points on triangle edges)");
        o.WriteLine();
        o.WriteLine("The reference moves each vertex to landblock-local space in double (normalised quaternion), fan-triangulates, and takes the topmost exact barycentric Z; no tolerance.");
        o.WriteLine();
        o.WriteLine("| measure | value |");
        o.WriteLine("| --- | ---: |");
        o.WriteLine($"| points where both find a floor, farther than 1 mm from every edge | {both} |");
        o.WriteLine($"| max \\|float − double\\| Z (m) | {E(max)} |");
        o.WriteLine($"| mean \\|float − double\\| Z (m) | {E(sum / Math.Max(both, 1))} |");
        o.WriteLine($"| points where both find a floor within 1 mm of an edge | {near} (max \\|float − double\\| {E(nearMax)} m: a stacked floor's edge) |");
        o.WriteLine($"| reference finds a floor, float does not | {refOnly} (farthest inside an edge: {E(worstRefOnlyEdge)} m) |");
        o.WriteLine($"| float finds a floor, reference does not | {floatOnly} (farthest outside an edge: {E(worstFloatOnlyEdge)} m; tolerance 2e-4 m) |");
        o.WriteLine($"| points on an edge with no floor found | {edgeMisses} of {edgeTotal} |");
        o.WriteLine();
    }

    /// <summary>A convex polygon, counter-clockwise from above, on a walkable plane (slope ≤ 0.3), cell-local.</summary>
    private static Vector3[] RandomFloorPolygon(Random random)
    {
        int k = random.Next(3, 9);
        var angles = new double[k];
        for (int i = 0; i < k; i++)
        {
            angles[i] = random.NextDouble() * 2 * Math.PI;
        }

        Array.Sort(angles);
        float cx = (random.NextSingle() - 0.5f) * 20f, cy = (random.NextSingle() - 0.5f) * 20f, r = 0.5f + (random.NextSingle() * 4.5f);
        float z0 = random.NextSingle() * 6f, sx = (random.NextSingle() - 0.5f) * 0.6f, sy = (random.NextSingle() - 0.5f) * 0.6f;
        var v = new Vector3[k];
        for (int i = 0; i < k; i++)
        {
            float x = cx + (r * (float)Math.Cos(angles[i])), y = cy + (r * (float)Math.Sin(angles[i]));
            v[i] = new Vector3(x, y, z0 + (sx * x) + (sy * y));
        }

        return v;
    }

    // ---------------------------------------------------------------- course

    private enum Obstacle
    {
        ThinWall,
        RaisedStrip,
        Pit,
        TerrainCliff,
    }

    private static readonly int[] Speeds = [1, 5, 10, 20, 50];

    /// <summary>Frames per second of the obstacle course.</summary>
    private const float CourseHz = 30f;

    /// <summary>The step down of the course's configurations that have one (metres).</summary>
    private const float StepDown = 1.5f;

    /// <summary>The caller's gravity on the course for a mover left in the air (step down), m/s².</summary>
    private const float Gravity = 9.81f;

    /// <summary>
    /// After <see cref="Run"/>: each course configuration's overall miss rate (percent of the courses
    /// the truth stops in that the configuration gets past, all obstacles and speeds), for the chart.
    /// </summary>
    public static IReadOnlyList<(string Name, double MissPercent)> CourseMissRates { get; private set; } = [];

    /// <summary>
    /// "Past the far edge" means more than 5 cm past it: a mover stopped against the far wall of a
    /// pit stands up to the 0.2 mm edge tolerance beyond it, which is not getting past.
    /// </summary>
    private const float PassMargin = 0.05f;

    private static void Course(TextWriter o)
    {
        const int Trials = 400;
        const float Hz = CourseHz;
        var configs = new (string Name, MovementOptions Options)[]
        {
            ("end-point (literal)", default),
            ("swept 0.48 m", new MovementOptions { SweepStepLength = 0.48f }),
            ("walkable slope", new MovementOptions { WalkableSlope = true }),
            ("swept 0.48 m + walkable slope", new MovementOptions { SweepStepLength = 0.48f, WalkableSlope = true }),
            ("step down 1.5 m", new MovementOptions { StepDownHeight = StepDown }),
            ("doors only", new MovementOptions { DoorsOnly = true }),
            ("body (the player's)", new MovementOptions { Body = MoverBody.Player }),
            ("Player without body", MovementOptions.Player with { Body = null }),
            ("Player (all effects, body)", MovementOptions.Player),
        };
        // The truth: a point in 1 cm sub-steps with the walkable-slope limit; for a configuration with
        // step down (which turns a drop into a fall), the same with step down 1.5 m and the caller's gravity.
        var references = new MovementOptions[]
        {
            new() { SweepStepLength = 0.01f, WalkableSlope = true },
            new() { SweepStepLength = 0.01f, WalkableSlope = true, StepDownHeight = StepDown },
        };
        int[] truthOf = [.. configs.Select(c => c.Options.StepDownHeight switch
        {
            null => 0,
            StepDown => 1,
            float other => throw new InvalidOperationException($"{c.Name}: step down {other} m has no truth here (only {StepDown} m)."),
        })];

        // misses[obstacle, speed, config], falseStops[...], shouldStop[obstacle, speed, truth], shouldPass[...]
        var kinds = Enum.GetValues<Obstacle>();
        var misses = new int[kinds.Length, Speeds.Length, configs.Length];
        var falseStops = new int[kinds.Length, Speeds.Length, configs.Length];
        var shouldStop = new int[kinds.Length, Speeds.Length, references.Length];
        var shouldPass = new int[kinds.Length, Speeds.Length, references.Length];
        var refPassed = new bool[references.Length];
        var random = new Random(5);
        var engine = new PhysicsEngine(World.Holtburg);
        foreach (Obstacle kind in kinds)
        {
            for (int t = 0; t < Trials; t++)
            {
                CourseCase course = BuildCourse(kind, random, engine);
                for (int s = 0; s < Speeds.Length; s++)
                {
                    float step = Speeds[s] / Hz;
                    int frames = (int)MathF.Ceiling(course.Travel / step);
                    for (int r = 0; r < references.Length; r++)
                    {
                        refPassed[r] = Walk(engine, course, step, frames, references[r]) > course.FarEdge + PassMargin;
                        if (refPassed[r])
                        {
                            shouldPass[(int)kind, s, r]++;
                        }
                        else
                        {
                            shouldStop[(int)kind, s, r]++;
                        }
                    }

                    for (int c = 0; c < configs.Length; c++)
                    {
                        bool passed = Walk(engine, course, step, frames, configs[c].Options) > course.FarEdge + PassMargin;
                        bool truth = refPassed[truthOf[c]];
                        if (passed && !truth)
                        {
                            misses[(int)kind, s, c]++;
                        }
                        else if (!passed && truth)
                        {
                            falseStops[(int)kind, s, c]++;
                        }
                    }
                }
            }
        }

        o.WriteLine($"## Swept vs end-point movement: an obstacle course ({Trials} seeded courses per obstacle, speeds at 30 Hz)");
        o.WriteLine();
        o.WriteLine("Each course is one obstacle across a straight run, built from engine pieces and turned by a random yaw:");
        o.WriteLine("- **thin wall**: a cell whose floor stops and resumes after a 0.05–0.5 m strip with no floor (wall polygons stand there);");
        o.WriteLine("- **raised strip**: in the same cell, a 0.05–0.5 m wide floor strip 0.6–1.5 m above the floor (more than the 0.5 m step);");
        o.WriteLine("- **pit**: a 0.2–1.5 m wide strip of floor 3 m below (a mover falls in and cannot climb out);");
        o.WriteLine("- **terrain cliff**: the game's triangle terrain rising 10–60 m over 24 m (slope 0.4–2.5; steeper than 1.125 is not walkable).");
        o.WriteLine();
        o.WriteLine("The mover starts 0.5–4.5 m before the obstacle and is resolved frame by frame at `speed / 30` m per frame, step height 0.5 m;");
        o.WriteLine($"with step down, a mover left in the air falls under the caller's gravity ({Gravity} m/s², step down 0 while falling, as `MovementOptions.StepDownHeight` asks).");
        o.WriteLine("The truth is the most accurate configuration: 1 cm sub-steps with the walkable-slope limit. A **miss** is a run that ends beyond the");
        o.WriteLine("obstacle's far edge (by more than 5 cm) where the truth stopped before it; a **false stop** ends before it where the truth got past.");
        o.WriteLine($"A configuration with step down is judged against the same truth with step down {StepDown} m and gravity (a runner crosses a pit it");
        o.WriteLine("would have snapped into: that is the effect, not an error); its should-stop / should-pass counts are in the summary below.");
        o.WriteLine("Cells: `miss % / false-stop %` of the courses that should stop / pass (the row's counts: the truth without step down).");
        o.WriteLine();
        foreach (Obstacle kind in kinds)
        {
            o.Write($"| {kind} (should stop / pass) |");
            foreach (var c in configs)
            {
                o.Write($" {c.Name} |");
            }

            o.WriteLine();
            o.Write("| --- |");
            foreach (var _ in configs)
            {
                o.Write(" ---: |");
            }

            o.WriteLine();
            for (int s = 0; s < Speeds.Length; s++)
            {
                o.Write($"| {Speeds[s]} m/s ({F(Speeds[s] / Hz, "0.000")} m/frame; {shouldStop[(int)kind, s, 0]} / {shouldPass[(int)kind, s, 0]}) |");
                for (int c = 0; c < configs.Length; c++)
                {
                    int stop = shouldStop[(int)kind, s, truthOf[c]], pass = shouldPass[(int)kind, s, truthOf[c]];
                    o.Write($" {Pct(misses[(int)kind, s, c], stop)} / {Pct(falseStops[(int)kind, s, c], pass)} |");
                }

                o.WriteLine();
            }

            o.WriteLine();
        }

        // Overall miss rate per configuration, for the table and the chart.
        var missRates = new List<(string, double)>();
        o.WriteLine("| configuration | misses, all obstacles and speeds | misses at ≥ 20 m/s | false stops, all |");
        o.WriteLine("| --- | ---: | ---: | ---: |");
        for (int c = 0; c < configs.Length; c++)
        {
            int m = 0, stop = 0, mFast = 0, stopFast = 0, f = 0, pass = 0;
            foreach (Obstacle kind in kinds)
            {
                for (int s = 0; s < Speeds.Length; s++)
                {
                    m += misses[(int)kind, s, c];
                    stop += shouldStop[(int)kind, s, truthOf[c]];
                    f += falseStops[(int)kind, s, c];
                    pass += shouldPass[(int)kind, s, truthOf[c]];
                    if (Speeds[s] >= 20)
                    {
                        mFast += misses[(int)kind, s, c];
                        stopFast += shouldStop[(int)kind, s, truthOf[c]];
                    }
                }
            }

            o.WriteLine($"| {configs[c].Name} | {Pct(m, stop)} ({m}/{stop}) | {Pct(mFast, stopFast)} ({mFast}/{stopFast}) | {Pct(f, pass)} ({f}/{pass}) |");
            missRates.Add((configs[c].Name, 100.0 * m / stop));
        }

        CourseMissRates = missRates;

        o.WriteLine();
    }

    private static string Pct(int n, int of) => of == 0 ? "–" : F(100.0 * n / of, "0.0") + " %";

    private sealed record CourseCase(Vector3 Start, uint StartCell, Vector2 Direction, float Travel, float FarEdge);

    /// <summary>Builds one course into <paramref name="engine"/> (replacing Holtburg) and says where it starts and what "past it" is.</summary>
    private static CourseCase BuildCourse(Obstacle kind, Random random, PhysicsEngine engine)
    {
        float yaw = random.NextSingle() * 2 * MathF.PI;
        Quaternion q = Quaternion.CreateFromAxisAngle(Vector3.UnitZ, yaw);
        var direction = new Vector2(MathF.Cos(yaw), MathF.Sin(yaw));
        float startX = 0.5f + (random.NextSingle() * 4f), startY = (random.NextSingle() - 0.5f) * 1.5f;
        if (kind == Obstacle.TerrainCliff)
        {
            // Outdoors, along +x only (terrain is axis-aligned): column 2 (x = 48) at the foot, column 3 (x = 72) raised.
            float rise = 10f + (random.NextSingle() * 50f);
            var table = new float[256];
            for (int i = 0; i < 256; i++)
            {
                table[i] = i * 0.25f;
            }

            var heights = new byte[81];
            for (int y = 0; y < 9; y++)
            {
                heights[(3 * 9) + y] = (byte)MathF.Round(rise / 0.25f);
            }

            engine.AddLandblock(World.Holtburg, new TerrainSurface(heights, table, World.Holtburg), []);
            float x0 = 48f - startX, y0 = 100f + (startY * 10f);
            return new CourseCase(new Vector3(x0, y0, 0f), 0xA9B40000u | World.OutdoorCell(x0, y0), Vector2.UnitX, 72f - x0 + 6f, 72f - x0);
        }

        // Indoors: a corridor along cell-local +x, y in [-1, 1]: floor [0, 5], obstacle [5, 5 + w], floor [5 + w, 12].
        float w = kind == Obstacle.Pit ? 0.2f + (random.NextSingle() * 1.3f) : 0.05f + (random.NextSingle() * 0.45f);
        var origin = new Vector3(60f + (random.NextSingle() * 60f), 60f + (random.NextSingle() * 60f), 50f);
        var b = new CellBuilder(0xA9B40100u, origin, q);
        b.Floor(0, -1, 5, 1, 0);
        b.Floor(5 + w, -1, 12, 1, 0);
        switch (kind)
        {
            case Obstacle.ThinWall:
                b.Physics(World.Wall(5, -1, 5, 1, 0, 3));
                b.Physics(World.Wall(5 + w, 1, 5 + w, -1, 0, 3));
                break;
            case Obstacle.RaisedStrip:
                b.Floor(5, -1, 5 + w, 1, 0.6f + (random.NextSingle() * 0.9f));
                break;
            case Obstacle.Pit:
                b.Floor(5, -1, 5 + w, 1, -3f);
                break;
        }

        engine.AddLandblock(World.Holtburg, new TerrainSurface(new byte[81], World.ConstantTable(0f), World.Holtburg), [b.Build()]);
        Vector3 start = origin + Vector3.Transform(new Vector3(startX, startY, 0f), q);
        return new CourseCase(start, 0xA9B40100u, direction, 10f, 5f + w - startX);
    }

    /// <summary>Walks the course; returns how far along its direction the mover got (metres).</summary>
    private static float Walk(PhysicsEngine engine, CourseCase course, float step, int frames, in MovementOptions options)
    {
        Vector3 pos = course.Start;
        uint cell = course.StartCell;
        var delta = new Vector3(course.Direction * step, 0f);
        MovementOptions falling = options.StepDownHeight is null ? options : options with { StepDownHeight = 0f };
        bool vertical = options.Vertical && options.Body.HasValue; // the engine moves the body down by the delta's Z
        float fallSpeed = 0f;
        for (int f = 0; f < frames; f++)
        {
            MovementOptions now = fallSpeed > 0f && !vertical ? falling : options;
            ResolveResult r = engine.Resolve(pos, cell, vertical ? delta with { Z = -fallSpeed / CourseHz } : delta, World.PlayerStepUp, in now);
            pos = r.Position;
            cell = r.CellId;

            // The caller's gravity: only step down leaves a mover in the air above the ground here.
            if (options.StepDownHeight is not null && !r.IsOnGround)
            {
                fallSpeed += Gravity / CourseHz;
                pos.Z -= vertical ? 0f : fallSpeed / CourseHz;
            }
            else
            {
                fallSpeed = 0f;
            }
        }

        return Vector2.Dot(new Vector2(pos.X - course.Start.X, pos.Y - course.Start.Y), course.Direction);
    }

    // ---------------------------------------------------------------- walkable slope

    private static void Slopes(TextWriter o)
    {
        const int Landblocks = 100, Moves = 200;
        var random = new Random(5);
        float[] table = World.NonLinearTable();
        var engine = new PhysicsEngine(World.Holtburg);
        var on = new MovementOptions { WalkableSlope = true };
        int attempts = 0, steepUphill = 0, climbedOff = 0, climbedOn = 0, acceptedOff = 0, acceptedOn = 0;
        double steepArea = 0;
        for (int l = 0; l < Landblocks; l++)
        {
            byte[] heights = World.RollingHeights(random, 40, 1 + random.Next(8));
            engine.AddLandblock(World.Holtburg, new TerrainSurface(heights, table, World.Holtburg), []);
            var reference = new ReferenceTerrain(heights, table, World.Holtburg);
            for (int m = 0; m < Moves; m++)
            {
                float x = 2f + (random.NextSingle() * 188f), y = 2f + (random.NextSingle() * 188f);
                var pos = new Vector3(x, y, (float)reference.Sample(x, y).Z);
                uint cell = 0xA9B40000u | World.OutdoorCell(x, y);
                Vector3 delta = World.RandomDelta(random, 0.1f, 0.3f);
                attempts++;
                (double endZ, double endNormalZ) = reference.Sample(x + delta.X, y + delta.Y);
                bool steep = endNormalZ < PhysicsConstants.FloorZ;
                steepArea += reference.Sample(x, y).NormalZ < PhysicsConstants.FloorZ ? 1 : 0;
                bool uphill = endZ > pos.Z;
                if (steep && uphill)
                {
                    steepUphill++;
                }

                ResolveResult off = engine.Resolve(pos, cell, delta, World.PlayerStepUp);
                ResolveResult with = engine.Resolve(pos, cell, delta, World.PlayerStepUp, in on);
                acceptedOff += off.Position != pos ? 1 : 0;
                acceptedOn += with.Position != pos ? 1 : 0;
                climbedOff += Forbidden(off, pos, reference) ? 1 : 0;
                climbedOn += Forbidden(with, pos, reference) ? 1 : 0;
            }
        }

        o.WriteLine($"## Walkable slope on vs off ({Landblocks} rolling landblocks, index 40 ± 1..8 of the non-linear table, × {Moves} moves of 0.1–0.3 m, game triangles, step 0.5 m)");
        o.WriteLine();
        o.WriteLine($"A **forbidden climb** is an accepted move that ends higher than it started on terrain whose unit normal Z (double-precision reference) is below FloorZ = {PhysicsConstants.FloorZ.ToString(Inv)}.");
        o.WriteLine($"{Pct((int)steepArea, attempts)} of the start points stand on unwalkable slopes; {steepUphill} of {attempts} moves ({Pct(steepUphill, attempts)}) head uphill onto one.");
        o.WriteLine();
        o.WriteLine("| walkable slope | moves accepted | forbidden climbs | of the moves heading up a forbidden slope |");
        o.WriteLine("| --- | ---: | ---: | ---: |");
        o.WriteLine($"| off (literal) | {acceptedOff} | {climbedOff} ({Pct(climbedOff, attempts)}) | {Pct(climbedOff, steepUphill)} |");
        o.WriteLine($"| on | {acceptedOn} | {climbedOn} ({Pct(climbedOn, attempts)}) | {Pct(climbedOn, steepUphill)} |");
        o.WriteLine();
    }

    private static bool Forbidden(ResolveResult r, Vector3 start, ReferenceTerrain reference) =>
        r.Position != start && r.Position.Z > start.Z && reference.Sample(r.Position.X, r.Position.Y).NormalZ < PhysicsConstants.FloorZ;

    // ---------------------------------------------------------------- doors only

    private static void DoorsOnly(TextWriter o)
    {
        const int Moves = 20000;
        o.WriteLine($"## Doors only on vs off ({Moves} moves per row starting 1 mm to 0.5 m outside 64 one-room buildings with a 1 m door)");
        o.WriteLine();
        o.WriteLine("| doors only | moves | entries into a building | through a wall (not across the door opening) | refused at the door (crossed the opening, stayed out) |");
        o.WriteLine("| --- | --- | ---: | ---: | ---: |");
        foreach ((float min, float max) in new[] { (0.1f, 0.3f), (0.3f, 1.5f) })
        {
            DoorsOnlyRow(o, Moves, min, max);
        }

        o.WriteLine();
    }

    private static void DoorsOnlyRow(TextWriter o, int moves, float minMove, float maxMove)
    {
        // Starts within 1 mm of a floor's edge are on that floor already (0.2 mm tolerance): excluded.
        const float Margin = 0.001f;
        var random = new Random(5);
        var engine = new PhysicsEngine(World.Holtburg);
        var terrain = new TerrainSurface(new byte[81], World.ConstantTable(10f), World.Holtburg);
        engine.AddLandblock(World.Holtburg, terrain, World.Buildings(World.Holtburg, terrain, 64));
        var on = new MovementOptions { DoorsOnly = true };
        int literalEntries = 0, literalThroughWall = 0, literalRefused = 0, doorsEntries = 0, doorsThroughWall = 0, doorsRefused = 0;
        for (int m = 0; m < moves; m++)
        {
            // Start within 0.5 m outside one of the 64 rooms (6 m squares).
            int i = random.Next(64);
            int outdoor = i % 32;
            float ox = 96f + ((outdoor / 8) * 24f) + (i < 32 ? 3f : 14f), oy = ((outdoor % 8) * 24f) + (i < 32 ? 3f : 14f);
            float x, y;
            do
            {
                x = ox - 0.5f + (random.NextSingle() * 7f);
                y = oy - 0.5f + (random.NextSingle() * 7f);
            }
            while (x > ox - Margin && x < ox + 6 + Margin && y > oy - Margin && y < oy + 6 + Margin);

            var pos = new Vector3(x, y, 10f);
            uint cell = 0xA9B40000u | World.OutdoorCell(x, y);
            Vector3 delta = World.RandomDelta(random, minMove, maxMove);
            bool door = CrossesDoor(new Vector2(x, y), new Vector2(x + delta.X, y + delta.Y), ox, oy);
            ResolveResult a = engine.Resolve(pos, cell, delta, World.PlayerStepUp);
            ResolveResult b = engine.Resolve(pos, cell, delta, World.PlayerStepUp, in on);
            Count(a, door, ref literalEntries, ref literalThroughWall, ref literalRefused);
            Count(b, door, ref doorsEntries, ref doorsThroughWall, ref doorsRefused);
        }

        string range = FormattableString.Invariant($"{minMove}–{maxMove} m");
        o.WriteLine($"| off (literal) | {range} | {literalEntries} | {literalThroughWall} ({Pct(literalThroughWall, Math.Max(literalEntries, 1))}) | {literalRefused} |");
        o.WriteLine($"| on | {range} | {doorsEntries} | {doorsThroughWall} | {doorsRefused} |");

        static void Count(ResolveResult r, bool door, ref int entries, ref int throughWall, ref int refused)
        {
            if ((r.CellId & 0xFFFF) >= 0x100)
            {
                entries++;
                throughWall += door ? 0 : 1;
            }
            else if (door)
            {
                refused++;
            }
        }
    }

    /// <summary>Whether p0 → p1 crosses the south wall's door opening (y = oy, x in [ox + 2.5, ox + 3.5]) inward.</summary>
    private static bool CrossesDoor(Vector2 p0, Vector2 p1, float ox, float oy)
    {
        if (!(p0.Y < oy && p1.Y >= oy))
        {
            return false;
        }

        float t = (oy - p0.Y) / (p1.Y - p0.Y);
        float x = p0.X + (t * (p1.X - p0.X));
        return x >= ox + 2.5f && x <= ox + 3.5f;
    }
}
