using System.Globalization;
using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Physics;
using AcDream.Testing;

namespace AcDream.Core.Benchmarks;

/// <summary>
/// <c>--accuracy</c>, the body's rows: the engine's body against <see cref="ReferenceBody"/>, a
/// double-precision reference of the same model (an upright cylinder; walls cut to its height band,
/// seen from above; collide and slide) that moves in 0.1 mm sub-steps with exact push-out. The worlds
/// are <see cref="BodyCourses"/> and the real Holtburg cells. Every figure is recomputed from seeded
/// generators; the run takes well under a minute.
/// </summary>
internal static class BodyAccuracy
{
    private const float Step = 0.5f;

    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    private static readonly int[] Speeds = [1, 5, 10, 20, 50];

    public static void Run(TextWriter o)
    {
        o.WriteLine("## Body: against a double-precision reference (0.1 mm sub-steps, exact push-out)");
        o.WriteLine();
        o.WriteLine("The reference (`tests/Shared/ReferenceBody.cs`) is written from the model, not the engine: it places the cells' wall polygons");
        o.WriteLine("in double precision from their own definitions, cuts them to the body's band (step height above the feet to its top),");
        o.WriteLine("moves the centre in 0.1 mm sub-steps, pushes it out to the clearance from every edge it comes within, and from a contact");
        o.WriteLine("on slides along the wall (a corner, a wedge or the 4th contact stops it). Its clearance is the body's radius plus the");
        o.WriteLine("skin the engine documents (1e-5 m + twice the float spacing of the coordinates); overlap is measured against the radius alone.");
        o.WriteLine("Each call is compared from the engine's own start. A call is compared for its end position when it is well-conditioned:");
        o.WriteLine("when growing or shrinking the reference's clearance by 0.1 mm (or two float spacings of the world frame, where more)");
        o.WriteLine("moves its end by less than 0.5 mm plus 1.5 times that, and turning its move 1 mrad either way by less than 0.5 mm plus");
        o.WriteLine("twice what the turn itself does (a grazing touch of a wall's end turns a slide by the square root of the depth; whether");
        o.WriteLine("a wedge stops the body can turn on a hair).");
        o.WriteLine();
        Speed(o);
        Sliding(o);
        Doorways(o);
    }

    private static string Mm(double metres) => (metres * 1000).ToString("0.000", Inv);

    private static string Pct(int n, int of) => of == 0 ? "–" : n == of ? "100 %" : (Math.Floor(1000.0 * n / of) / 10).ToString("0.0", Inv) + " %";

    /// <summary>Overlap in mm, or how far clear the closest call stayed.</summary>
    private static string Overlap(double metres) => metres > 0 ? $"{Mm(metres)} mm" : $"none ({Mm(-metres)} mm clear)";

    // ---------------------------------------------------------------- speed

    private static void Speed(TextWriter o)
    {
        const int Courses = 16, Walks = 3;
        o.WriteLine($"### Fast movers into walls ({Courses} rooms per row, each closed off in two by a partition of zero thickness, {Walks} movers each)");
        o.WriteLine();
        o.WriteLine("Rooms 6–12 × 4–9 m turned by a random yaw, half in the global frame, a quarter in landblocks at the world's far edge (0xFE);");
        o.WriteLine("the player's body or one of radius 0.2–0.6 m, with or without the other effects. Each mover starts west of the partition and walks");
        o.WriteLine("6 m (or 1 s) at the partition or at a random wall, up to 75° off its normal. **Tunnelled**: a call that ends across a wall from");
        o.WriteLine("where the reference ends, or east of the partition. Targets: overlap ≤ 1 mm, tunnelled 0.");
        o.WriteLine();
        o.WriteLine("| speed | per call | calls | meeting a wall | largest overlap, centred frame | largest overlap, global frame | tunnelled |");
        o.WriteLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: |");
        foreach (int hz in new[] { 30, 10 })
        {
            foreach (int speed in Speeds)
            {
                var random = new Random((speed * 100) + hz + 5);
                float length = (float)speed / hz;
                int calls = 0, atWalls = 0, tunnelled = 0;
                double centred = double.NegativeInfinity, global = double.NegativeInfinity;
                for (int c = 0; c < Courses; c++)
                {
                    bool inGlobal = c % 2 == 0;
                    int lb = c % 4 == 0 ? 0xFE : random.Next(1, 254);
                    BodyCourse course = BodyCourses.Build(BodyCourses.Kind.Partition, random, lb, random.Next(1, 254), inGlobal);
                    MoverBody body = c % 3 == 0 ? new MoverBody(BodyCourses.Range(random, 0.2f, 0.6f), 1.8f) : MoverBody.Player;
                    MovementOptions options = c % 2 == 0 ? new MovementOptions { Body = body } : MovementOptions.Player with { Body = body };
                    (uint startCell, AcDream.Core.Dat.Frame frame, Vector2 _, Vector2 west) = course.Areas[0];
                    for (int walk = 0; walk < Walks; walk++)
                    {
                        if (course.RandomStart(random, body, Step, 0.01f) is not (Vector3 pos, uint cell))
                        {
                            continue;
                        }

                        float yaw = walk == 0 ? 0f : random.Next(4) * MathF.PI / 2;
                        float aim = yaw + BodyCourses.Range(random, -1.3f, 1.3f);
                        Vector3 direction = Vector3.Transform(new Vector3(MathF.Cos(aim), MathF.Sin(aim), 0), frame.Orientation);
                        var delta = new Vector3(direction.X, direction.Y, 0) * length;
                        for (int f = 0; f < Math.Max(hz, hz * 6 / speed); f++)
                        {
                            BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, options);
                            calls++;
                            atWalls += call.Engine.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall ? 1 : 0;
                            tunnelled += call.Tunnelled || course.CellLocal(frame, call.Engine.Position).X >= west.X ? 1 : 0;
                            if (inGlobal)
                            {
                                global = Math.Max(global, call.Overlap);
                            }
                            else
                            {
                                centred = Math.Max(centred, call.Overlap);
                            }

                            (pos, cell) = (call.Engine.Position, call.Engine.CellId);
                        }
                    }
                }

                o.WriteLine($"| {speed} m/s at {hz} Hz | {length.ToString("0.###", Inv)} m | {calls} | {Pct(atWalls, calls)} | {Overlap(centred)} | {Overlap(global)} | {tunnelled} |");
            }
        }

        o.WriteLine();
    }

    // ---------------------------------------------------------------- sliding courses

    private static void Sliding(TextWriter o)
    {
        const int CoursesPerKind = 16, Walks = 4, Moves = 25;
        BodyCourses.Kind[] kinds = Enum.GetValues<BodyCourses.Kind>();
        o.WriteLine($"### Sliding courses ({kinds.Length} kinds × {CoursesPerKind} courses per frame, {Walks} movers × {Moves} moves each)");
        o.WriteLine();
        o.WriteLine("Kinds: a room, a corridor, an L-shaped room (its reflex corner, sometimes a 135° diagonal), two rooms through a doorway in a");
        o.WriteLine("shared wall of zero thickness, two rooms through a 0.4 m door cell, a room with free-standing walls of zero thickness, a pillar,");
        o.WriteLine("a parapet, a curb and a beam, a partitioned room; walls often cut into collinear pieces; cells turned by a random yaw, some");
        o.WriteLine("quaternions non-unit; a third of the landblocks at the world's far edge (0xFE: in the global frame the float spacing there is");
        o.WriteLine("3.9 mm, so the end-position target there is 1 mm + 4 spacings). Movers hold a direction for a while (so they slide along");
        o.WriteLine("walls), moves of 0.05, 0.3, 1 and 2 m, the player's body or a random one (radius 0.2–0.6 m, 1–2 m tall). Target: end");
        o.WriteLine("positions within 1 mm of the reference's.");
        o.WriteLine();
        o.WriteLine("| frame | calls | slid | compared | max \\|engine − reference\\| | within 1 mm | within 1 mm + 4 spacings | largest overlap | tunnelled |");
        o.WriteLine("| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |");
        foreach ((string name, bool global, bool farOnly) in new[] { ("centred on the landblock", false, false), ("global", true, false), ("global, far edge (0xFE) only", true, true) })
        {
            var random = new Random(5);
            int calls = 0, slid = 0, compared = 0, within = 0, withinTolerance = 0, tunnelled = 0;
            double worst = 0, overlap = double.NegativeInfinity;
            foreach (BodyCourses.Kind kind in kinds)
            {
                for (int c = 0; c < CoursesPerKind; c++)
                {
                    int lbX = farOnly || random.Next(3) == 0 ? 0xFE : random.Next(1, 254), lbY = random.Next(3) == 0 ? 0xFE : random.Next(1, 254);
                    BodyCourse course = BodyCourses.Build(kind, random, lbX, lbY, global);
                    MoverBody body = random.Next(3) == 0 ? new MoverBody(BodyCourses.Range(random, 0.2f, 0.6f), BodyCourses.Range(random, 1.0f, 2.0f)) : MoverBody.Player;
                    MovementOptions options = random.Next(2) == 0 ? new MovementOptions { Body = body } : MovementOptions.Player with { Body = body };
                    for (int walk = 0; walk < Walks; walk++)
                    {
                        if (course.RandomStart(random, body, Step, 0.01f) is not (Vector3 pos, uint cell))
                        {
                            continue;
                        }

                        float angle = random.NextSingle() * MathF.PI * 2;
                        for (int m = 0; m < Moves; m++)
                        {
                            angle = random.Next(4) == 0 ? random.NextSingle() * MathF.PI * 2 : angle;
                            float length = random.Next(5) switch { 0 => 2f, 1 => 1f, 2 => 0.05f, _ => 0.3f };
                            var delta = new Vector3(MathF.Cos(angle) * length, MathF.Sin(angle) * length, 0);
                            BodyCall call = BodyCheck.Compare(course, pos, cell, delta, Step, options);
                            calls++;
                            slid += call.Engine.Outcome == ResolveOutcome.Slid ? 1 : 0;
                            if (call.WellConditioned)
                            {
                                compared++;
                                worst = Math.Max(worst, call.Distance);
                                within += call.Distance <= BodyCheck.EndTolerance ? 1 : 0;
                                withinTolerance += call.Distance <= call.Tolerance ? 1 : 0;
                            }

                            overlap = Math.Max(overlap, call.Overlap);
                            tunnelled += call.Tunnelled ? 1 : 0;
                            (pos, cell) = (call.Engine.Position, call.Engine.CellId);
                        }
                    }
                }
            }

            o.WriteLine($"| {name} | {calls} | {Pct(slid, calls)} | {compared} | {Mm(worst)} mm | {within} ({Pct(within, compared)}) | {withinTolerance} | {Overlap(overlap)} | {tunnelled} |");
        }

        o.WriteLine();
    }

    // ---------------------------------------------------------------- Holtburg doorways

    private static void Doorways(TextWriter o)
    {
        List<CellFixtureReader.FixtureCell> fixtures = World.HoltburgFixtures();
        var walls = ReferenceBody.FromCells(fixtures.Select(c => (c.EnvCell, c.CellStruct)));
        var engine = new PhysicsEngine(World.Holtburg);
        engine.AddLandblock(World.Holtburg, new TerrainSurface(new byte[81], World.ConstantTable(World.HoltburgGroundZ), World.Holtburg), World.Surfaces(fixtures));
        engine.AddLandblock(0xA9B3FFFFu, new TerrainSurface(new byte[81], World.ConstantTable(World.HoltburgGroundZ), 0xA9B3FFFFu), []);
        float[] angles = [0f, 15f, -15f, 30f, -30f, 45f, -45f, 60f, -60f];

        o.WriteLine("### The real Holtburg doorways (flat terrain at 94 m, step 0.6 m, `MovementOptions.Player`)");
        o.WriteLine();
        o.WriteLine("Each doorway at floor level, both ways, walked at 0.15 m per frame from 0.2–1.4 m before it at 0°, ±15°, ±30°, ±45°, ±60° from");
        o.WriteLine("its normal (aimed at the opening's centre, or across it where the walls beside it leave no room to come at it from that side).");
        o.WriteLine("**Passed**: ends on the far side. The 1.9 m doors are also walked (0°, ±20°, ±45°) with a body 4 cm wider than the door.");
        o.WriteLine();
        o.WriteLine("| doorway | width | passed by the player's body (0.96 m) | a body 4 cm wider than the door |");
        o.WriteLine("| --- | ---: | --- | --- |");
        foreach (Doorway door in BodyDoorways.Real)
        {
            var passed = new List<float>();
            var tried = new List<float>();
            foreach (float degrees in angles)
            {
                if (BodyDoorways.Walk(engine, walls, door, degrees, MovementOptions.Player) is (List<uint> _, ResolveResult last))
                {
                    tried.Add(degrees);
                    if (BodyDoorways.IsSide(last.CellId, door.To))
                    {
                        passed.Add(degrees);
                    }
                }
            }

            string fat = "–";
            if (door.Width < 2f)
            {
                var wide = new MovementOptions { Body = new MoverBody((door.Width / 2) + 0.02f, 1.835f), DoorsOnly = true };
                int fatTried = 0, fatPassed = 0;
                foreach (float degrees in new[] { 0f, 20f, -20f, 45f, -45f })
                {
                    if (BodyDoorways.Walk(engine, walls, door with { Depth = MathF.Max(door.Depth, wide.Body!.Value.Radius + 0.05f) }, degrees, wide) is (List<uint> cells, ResolveResult _))
                    {
                        fatTried++;
                        fatPassed += cells.Any(c => BodyDoorways.IsSide(c, door.To) && !BodyDoorways.IsSide(c, door.From)) ? 1 : 0;
                    }
                }

                fat = $"passed {fatPassed} of {fatTried}";
            }

            string untried = tried.Count == angles.Length ? string.Empty : $"; no room to approach at {string.Join(", ", angles.Except(tried).Select(a => a.ToString("0", Inv)))}°";
            o.WriteLine($"| {door.Name} | {door.Width.ToString("0.###", Inv)} m | {passed.Count} of {tried.Count} angles{untried} | {fat} |");
        }

        o.WriteLine();
        o.WriteLine("Doorways lower than the player (the raised door cell 0x0142, 1.8 m; the north door's arch 0x014F, 1.5 m), with a 1.1 m step");
        o.WriteLine("standing in for the stairs the cells lack, at 0° and ±30°: a ceiling lower than the body above the floor it would stand on stops it.");
        o.WriteLine();
        o.WriteLine("| doorway | the player (1.835 m) | a body 1.2 m tall |");
        o.WriteLine("| --- | --- | --- |");
        foreach (Doorway door in BodyDoorways.Low)
        {
            int stopped = 0, tall = 0, passed = 0, shortTried = 0;
            foreach (float degrees in new[] { 0f, 30f, -30f })
            {
                if (BodyDoorways.Walk(engine, walls, door, degrees, MovementOptions.Player, step: 1.1f) is (List<uint> cells, ResolveResult _))
                {
                    tall++;
                    stopped += cells.Count == 1 ? 1 : 0;
                }

                if (BodyDoorways.Walk(engine, walls, door, degrees, MovementOptions.Player with { Body = new MoverBody(0.48f, 1.2f) }, step: 1.1f) is (List<uint> _, ResolveResult last))
                {
                    shortTried++;
                    passed += BodyDoorways.IsSide(last.CellId, door.To) ? 1 : 0;
                }
            }

            o.WriteLine($"| {door.Name} | stopped on its side {stopped} of {tall} | passed {passed} of {shortTried} |");
        }

        o.WriteLine();
    }
}
