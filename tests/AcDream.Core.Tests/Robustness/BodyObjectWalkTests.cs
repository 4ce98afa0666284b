using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// Seeded body walks among mixed objects (issue 29, item 10): 80 objects over two landblocks (real building shells,
/// stair pieces, closed boxes a step high and higher, door-sized slabs, beams on posts, thin walls, cylinders; a
/// quarter of them floating up to 1.6 m over the ground, some over the seam between the two landblocks), on flat land
/// and on hills, in the global frame, one centred on the walks' landblock and one centred across the world; the
/// player's body (0.48 × 1.835 m) and a small one (0.3 × 1.2 m), each with the player's point options (step down 1.5 m,
/// sweeps of 0.48 m, doors only, walkable slope), the body alone, and <see cref="MovementOptions.Player"/> (footing,
/// vertical motion, edge slide); steps of 0.2–1.2 m, moves of 5 cm to 2.8 m. Every answer keeps two invariants,
/// checked by brute force in double precision from the objects' own polygons (<see cref="ObjectKit.Floors"/>) and the
/// game's terrain (<see cref="Reference.TerrainZ"/>): <c>IsOnGround</c> is true exactly when the feet are within the
/// ground tolerance of the terrain or of an object's floor under the body's centre (with footing, of a floor within
/// the support reach, at its plane under the centre, no higher than its highest vertex); and no answer has the body's
/// centre inside a closed solid (a box or a slab) with any of its height, feet to top, inside the solid's. (Not
/// asserted: the disc's overlap of a solid's walls beside it, which a body stepping down off a box keeps where the
/// box's wall enters its band below its new feet plus the step.)
/// </summary>
public class BodyObjectWalkTests(ITestOutputHelper output)
{
    private const float Step = 0.5f;

    /// <summary>The walks' two landblocks at the far corner of the world (west, east), sharing a seam at x = 192.</summary>
    private static readonly uint[] Landblocks = [0xFDFDFFFFu, 0xFEFDFFFFu];

    public static TheoryData<string, string, int> Cases() => new()
    {
        { "flat", "global", 1001 }, { "hills", "global", 1002 }, { "flat", "centred", 1003 },
        { "hills", "centred", 1004 }, { "flat", "far-centred", 1005 }, { "hills", "far-centred", 1006 },
    };

    /// <summary>One solid the body must never end inside: an object-local box [−hx, hx] × [−hy, hy] × [0, h] placed by a frame.</summary>
    private sealed record Solid(Frame Frame, float Hx, float Hy, float H, string Name);

    /// <summary>A world: the engine, its two landblocks' terrains, every object floor in double, the closed solids.</summary>
    private sealed record World(PhysicsEngine Engine, Dictionary<uint, (byte[] Heights, float[] Table)> Land, Dictionary<uint, List<RefFloor>> Floors, Dictionary<uint, List<Solid>> Solids, List<(uint Landblock, Vector2 At)> Targets);

    [Theory]
    [MemberData(nameof(Cases))]
    public void Body_walks_among_objects_stand_where_a_floor_holds_them_and_never_end_inside_a_solid(string land, string frame, int seed)
    {
        var random = new Random(seed);
        World world = Build(random, land, frame);
        int answers = 0, checkedAnswers = 0, dishonest = 0, inside = 0, onObjects = 0, walled = 0;
        string? firstDishonest = null, firstInside = null;
        foreach (MoverBody body in new[] { MoverBody.Player, new MoverBody(0.3f, 1.2f) })
        {
            foreach (string effects in new[] { "point options", "alone", "Player" })
            {
                MovementOptions options = effects switch
                {
                    "alone" => new MovementOptions { Body = body },
                    "Player" => MovementOptions.Player with { Body = body },
                    _ => new MovementOptions { Body = body, StepDownHeight = 1.5f, SweepStepLength = 0.48f, DoorsOnly = true, WalkableSlope = true },
                };
                ResolveResult at = default;
                Vector3 target = default;
                float step = Step;
                string before = "";
                bool airborne = false;
                for (int m = 0; m < 3000; m++)
                {
                    if (m % 100 == 0 || at.Outcome == ResolveOutcome.Held)
                    {
                        (at, target) = Start(world, random, options);
                        step = 0.2f + (float)(random.NextDouble() * 1.0);
                    }

                    Vector2 toward = new(target.X - at.Position.X, target.Y - at.Position.Y);
                    float heading = m % 2 == 0 ? (float)(random.NextDouble() * 2 * Math.PI) : MathF.Atan2(toward.Y, toward.X) + (float)((random.NextDouble() - 0.5) * 2.0);
                    float length = random.Next(8) == 0 ? 2.8f : 0.05f + (float)(random.NextDouble() * 0.6);
                    var delta = new Vector3(MathF.Cos(heading) * length, MathF.Sin(heading) * length, options.Vertical && airborne ? -0.3f : 0f); // a body in the air falls by its delta
                    ResolveResult r = world.Engine.Resolve(at.Position, at.CellId, delta, step, options);
                    answers++;
                    string what = FormattableString.Invariant($"{land}, {frame}, body {body.Radius} × {body.Height}, {effects}, move {m}, step {step:R}: {at.Position:R} in 0x{at.CellId:X8} by {delta:R}");
                    walled += r.Outcome is ResolveOutcome.Slid or ResolveOutcome.Wall or ResolveOutcome.OuterWall ? 1 : 0;
                    if (r.Outcome != ResolveOutcome.Held)
                    {
                        (bool Stands, bool OnObject, string Ground)? honest = Honest(world, r, options.Footing ? body.Radius * PhysicsConstants.SupportReach : 0);
                        if (honest is (bool stands, bool onObject, string ground))
                        {
                            checkedAnswers++;
                            onObjects += stands && onObject ? 1 : 0;
                            if (stands != r.IsOnGround)
                            {
                                dishonest++;
                                firstDishonest ??= $"{what} → {r}; {ground}";
                            }
                        }

                        if (Inside(world, r, body) is string solid)
                        {
                            inside++;
                            firstInside ??= $"{what} → {r}: inside {solid}; before: {before}";
                        }
                    }

                    before = $"{what} → {r}";
                    at = r;
                    airborne = !r.IsOnGround;
                    if (airborne && !options.Vertical && (m / 100) % 2 == 0
                        && Inside(world, r with { Position = r.Position - new Vector3(0f, 0f, 0.3f) }, body, body.Radius + 0.01) is null)
                    {
                        at = r with { Position = r.Position - new Vector3(0f, 0f, 0.3f) }; // the walker's gravity, where the body drops clear of every solid
                    }
                }
            }
        }

        output.WriteLine($"{land}, {frame}: {answers} answers, {checkedAnswers} checked, {onObjects} on object floors, {walled} met walls; {dishonest} dishonest (first: {firstDishonest}); {inside} inside a solid (first: {firstInside})");
        dishonest.Should().Be(0, $"IsOnGround is true exactly where the terrain or an object's floor is at the feet; first: {firstDishonest}");
        inside.Should().Be(0, $"no body ends inside a closed solid; first: {firstInside}");
        checkedAnswers.Should().BeGreaterThan(answers * 8 / 10, "most answers are clear of the references' tolerance boundaries");
        onObjects.Should().BeGreaterThan(answers / 50, "the walks climb onto the objects");
        walled.Should().BeGreaterThan(answers / 20, "the bodies meet the objects' walls");
    }

    private static World Build(Random random, string land, string frame)
    {
        PhysicsEngine engine = frame switch
        {
            "global" => new PhysicsEngine(),
            "centred" => new PhysicsEngine(Landblocks[0]),
            _ => new PhysicsEngine(0x0202FFFFu),
        };
        float[] table = Enumerable.Range(0, 256).Select(i => 30f + (0.25f * i)).ToArray();
        var lands = new Dictionary<uint, (byte[], float[])>();
        var floors = new Dictionary<uint, List<RefFloor>>();
        var solids = new Dictionary<uint, List<Solid>>();
        var targets = new List<(uint, Vector2)>();
        foreach (uint landblock in Landblocks)
        {
            int x0 = CellIds.LandblockX(landblock) * 8, y0 = CellIds.LandblockY(landblock) * 8;
            byte[] heights = land == "flat"
                ? TestData.FlatHeights(60)
                : TestData.Heights((x, y) => 60 + (int)(14 * Math.Sin((x0 + x) * 0.9)) + (int)(10 * Math.Cos((y0 + y) * 0.7)));
            var terrain = new TerrainSurface(heights, table, landblock);
            (List<ObjectSurface> objects, List<RefFloor> placed, List<Solid> closed) = Objects(random, terrain, landblock == Landblocks[0]);
            engine.AddLandblock(landblock, terrain, [], objects);
            lands[landblock >> 16] = (heights, table);
            floors[landblock >> 16] = placed;
            solids[landblock >> 16] = closed;
            targets.AddRange(objects.Select(o => (landblock, new Vector2((o.BoundsMin.X + o.BoundsMax.X) / 2, (o.BoundsMin.Y + o.BoundsMax.Y) / 2))));
        }

        return new World(engine, lands, floors, solids, targets);
    }

    /// <summary>
    /// 40 objects of one landblock, each standing on the terrain (sunk 0.3 m into it, give or take 0.3 m) or, one in four,
    /// floating up to 1.6 m over it: the two real building shells, four stair pieces and a stair end, 17 closed boxes
    /// (alternately a step high and higher), three slabs, three beams (a bar on two posts at the waist or over a small
    /// body's head), four thin walls and six cylinders; in the west landblock one in four within 1.5 m of its east seam,
    /// reaching over it. Their floors (walkable polygons, and those at the walkable limit, which the check doubts) and
    /// their closed solids in double precision.
    /// </summary>
    private static (List<ObjectSurface>, List<RefFloor>, List<Solid>) Objects(Random random, TerrainSurface terrain, bool west)
    {
        var objects = new List<ObjectSurface>();
        var floors = new List<RefFloor>();
        var solids = new List<Solid>();
        uint nextId = 0x01000700u + (west ? 0u : 0x80u);
        (Setup tree, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree(0.4f, 6f);
        for (int i = 0; i < 40; i++)
        {
            bool seam = west && i % 4 == 0;
            float x = seam ? 190.5f + (float)(random.NextDouble() * 3) : west ? 142f + (float)(random.NextDouble() * 48) : 2f + (float)(random.NextDouble() * 48);
            float y = 80f + (float)(random.NextDouble() * 40);
            x = MathF.Min(x, 191.9f);
            float yaw = (float)(random.NextDouble() * 2 * Math.PI);
            float ground = terrain.SampleZ(x, y);
            float lift = random.Next(4) == 0 ? (float)(random.NextDouble() * 1.6) : (float)(random.NextDouble() * 0.6) - 0.3f; // some stand on the ground, some float over it
            Frame at = ObjectKit.At(new Vector3(x, y, ground - 0.3f + lift), yaw);
            GfxObj? gfx = null;
            switch (i)
            {
                case 0:
                    gfx = RealObjects.GfxObjs[ObjectPlacements.CottageShell];
                    at = ObjectKit.At(new Vector3(x, y, ground), yaw);
                    break;
                case 1:
                    gfx = RealObjects.GfxObjs[ObjectPlacements.SmallBuilding];
                    at = ObjectKit.At(new Vector3(x, y, ground), yaw);
                    break;
                case <= 5:
                    gfx = RealObjects.GfxObjs[ObjectPlacements.StairPiece];
                    at = ObjectKit.At(new Vector3(x, y, ground + (0.2f * (i - 2))), yaw);
                    break;
                case 6:
                    gfx = RealObjects.GfxObjs[0x01000ACA];
                    at = ObjectKit.At(new Vector3(x, y, ground), yaw);
                    break;
                case <= 11 or >= 28:
                {
                    // A closed box: a step high (its top a floor to climb onto) or higher than the step.
                    float hx = 0.4f + (float)(random.NextDouble() * 1.6), hy = 0.4f + (float)(random.NextDouble() * 1.6);
                    float h = 0.3f + (i % 2 == 0 ? 0.1f + (float)(random.NextDouble() * 0.35) : 0.8f + (float)(random.NextDouble() * 2));
                    gfx = Box(nextId++, hx, hy, h);
                    solids.Add(new Solid(at, hx, hy, h, $"box 0x{gfx.Id:X8}"));
                    break;
                }

                case <= 14:
                {
                    // A slab: a door's size, 4 to 10 cm thick.
                    float hx = 0.45f + (float)(random.NextDouble() * 0.3), hy = 0.02f + (float)(random.NextDouble() * 0.03), h = 2.5f;
                    gfx = Box(nextId++, hx, hy, h);
                    solids.Add(new Solid(at, hx, hy, h, $"slab 0x{gfx.Id:X8}"));
                    break;
                }

                case <= 17:
                {
                    // A beam: a bar 10–20 cm square at the waist or over a small body's head, on two posts.
                    float half = 1f + (float)(random.NextDouble() * 1.5), s = 0.05f + (float)(random.NextDouble() * 0.05);
                    float z = 0.3f + (i % 2 == 0 ? 1.0f : 1.3f + (float)(random.NextDouble() * 0.5));
                    gfx = ObjectKit.Gfx(nextId++, [.. BoxFaces(-half, -s, z, half, s, z + (2 * s)), .. BoxFaces(-half, -s, 0, (2 * s) - half, s, z), .. BoxFaces(half - (2 * s), -s, 0, half, s, z)]);
                    break;
                }

                case <= 21:
                {
                    float half = 0.5f + (float)(random.NextDouble() * 2);
                    gfx = ObjectKit.Gfx(nextId++, TestData.Wall(-half, 0, half, 0, 0, 2.8f));
                    break;
                }

                default:
                    objects.Add(new ObjectSurface(tree, parts, ObjectKit.At(new Vector3(x, y, ground - 0.3f), 0f), 0));
                    continue;
            }

            objects.Add(new ObjectSurface(gfx, at, 0));
            floors.AddRange(ObjectKit.Floors(gfx, at).Where(f => f.Walkable || Math.Abs(f.Nz - PhysicsConstants.FloorZ) < 1e-3));
        }

        return (objects, floors, solids);
    }

    /// <summary>A closed box GfxObj [−hx, hx] × [−hy, hy] × [0, h], six quads wound outward (its top a floor).</summary>
    private static GfxObj Box(uint id, float hx, float hy, float h) => ObjectKit.Gfx(id, BoxFaces(-hx, -hy, 0, hx, hy, h));

    private static Vector3[][] BoxFaces(float x0, float y0, float z0, float x1, float y1, float z1) =>
    [
        TestData.Square(x0, y0, x1, y1, z1),
        [new(x0, y0, z0), new(x0, y1, z0), new(x1, y1, z0), new(x1, y0, z0)],
        TestData.Wall(x0, y0, x1, y0, z0, z1), TestData.Wall(x1, y0, x1, y1, z0, z1),
        TestData.Wall(x1, y1, x0, y1, z0, z1), TestData.Wall(x0, y1, x0, y0, z0, z1),
    ];

    /// <summary>A start on the terrain within 8 m of an object of either landblock, settled by a zero move; and that object's centre, the walk's target.</summary>
    private static (ResolveResult Start, Vector3 Target) Start(World world, Random random, MovementOptions options)
    {
        while (true)
        {
            (uint landblock, Vector2 at) = world.Targets[random.Next(world.Targets.Count)];
            Vector3 origin = world.Engine.GetLandblockOrigin(landblock);
            Vector2 local = at + new Vector2((float)((random.NextDouble() * 16) - 8), (float)((random.NextDouble() * 16) - 8));
            local = Vector2.Clamp(local, new Vector2(1f), new Vector2(191f));
            var terrain = new TerrainSurface(world.Land[landblock >> 16].Heights, world.Land[landblock >> 16].Table, landblock);
            var position = origin + new Vector3(local, terrain.SampleZ(local.X, local.Y) + (float)((random.NextDouble() * 1.2) - 0.3));
            ResolveResult start = world.Engine.Resolve(position, landblock & 0xFFFF0000u, Vector3.Zero, Step, options);
            if (Inside(world, start, options.Body!.Value, options.Body!.Value.Radius + 0.01) is null)
            {
                return (start, origin + new Vector3(at, 0f)); // (a start whose body overlaps a solid is the walker's fault: not taken)
            }
        }
    }

    /// <summary>The answer's landblock and its landblock-local XY, in double.</summary>
    private static (uint Key, double X, double Y) Local(World world, ResolveResult r)
    {
        Vector3 origin = world.Engine.GetLandblockOrigin(r.CellId);
        return (r.CellId >> 16, (double)r.Position.X - origin.X, (double)r.Position.Y - origin.Y);
    }

    /// <summary>
    /// Whether the answer's feet stand on the terrain or an object's floor under its centre (any landblock's objects, in
    /// its frame), whether on an object's, and what was found; null where the reference is in doubt: within 1 mm plus
    /// the frame's rounding of a floor's edge or of the tolerance, or on a floor at the walkable limit.
    /// </summary>
    private static (bool Stands, bool OnObject, string Ground)? Honest(World world, ResolveResult r, double reach)
    {
        (uint key, double x, double y) = Local(world, r);
        if (!world.Land.TryGetValue(key, out (byte[] Heights, float[] Table) land) || x is < 0 or > 192 || y is < 0 or > 192)
        {
            return null;
        }

        // The answer's world XY is exactly where the engine sampled its ground (the world frame's representable point), so
        // the doubt is the float arithmetic of landblock-local metres (1.5e-5 m at 192 m), the floors' float placement and the Z's.
        const double spacing = 1.6e-5, margin = 1e-3;
        double z = r.Position.Z;
        double terrain = Reference.TerrainZ(land.Heights, land.Table, (int)(key >> 8), (int)(key & 0xFF), x, y);
        double nearest = Math.Abs(z - terrain);
        bool onObject = false, inDoubt = false;

        // In doubt: a surface of slope s within the float arithmetic of the tolerance, and a terrain whose triangle changes within it.
        void Doubt(double distance, double slope) => inDoubt |= Math.Abs(distance - PhysicsConstants.GroundTolerance) < 2e-5 + (Math.Abs(z) * 3e-7) + (slope * spacing);
        for (int corner = 0; corner < 4; corner++)
        {
            double cx = x + ((corner % 2 == 0 ? -1 : 1) * spacing), cy = y + ((corner / 2 == 0 ? -1 : 1) * spacing);
            inDoubt |= (Math.Abs(z - Reference.TerrainZ(land.Heights, land.Table, (int)(key >> 8), (int)(key & 0xFF), cx, cy)) <= PhysicsConstants.GroundTolerance) != (nearest <= PhysicsConstants.GroundTolerance);
        }

        Doubt(nearest, 0);
        foreach ((uint other, List<RefFloor> floors) in world.Floors)
        {
            double dx = (((int)(other >> 8) - (int)(key >> 8)) * 192.0), dy = (((int)(other & 0xFF) - (int)(key & 0xFF)) * 192.0);
            double ox = x - dx, oy = y - dy; // the answer in that landblock's frame
            foreach (RefFloor f in floors)
            {
                if (ox < f.MinX - margin - reach || ox > f.MaxX + margin + reach || oy < f.MinY - margin - reach || oy > f.MaxY + margin + reach)
                {
                    continue;
                }

                double edge = reach - Outside(f, ox, oy); // positive: within the reach of the floor (inside it for a point)
                double fz = Math.Min(f.ZAt(ox, oy), f.V.Max(v => v.Z));
                if (Math.Abs(edge) < margin && Math.Abs(fz - z) < 0.01)
                {
                    return null; // on a floor's edge
                }

                if (edge < 0)
                {
                    continue;
                }

                if (!f.Walkable)
                {
                    return null; // at the walkable limit
                }

                Doubt(Math.Abs(fz - z), Math.Sqrt(Math.Max(0, 1 - (f.Nz * f.Nz))) / f.Nz);
                if (Math.Abs(fz - z) < nearest)
                {
                    (nearest, onObject) = (Math.Abs(fz - z), true);
                }
            }
        }

        if (inDoubt)
        {
            return null;
        }

        return (nearest <= PhysicsConstants.GroundTolerance, onObject, FormattableString.Invariant($"terrain {terrain:R}, nearest floor {nearest:R} from the feet (on an object's: {onObject})"));
    }

    /// <summary>The distance seen from above from (x, y) to the floor's polygon, 0 inside it (or, inside, minus the distance to its nearest edge).</summary>
    private static double Outside(RefFloor f, double x, double y)
    {
        double inside = f.SignedInside(x, y);
        if (inside >= 0)
        {
            return -inside;
        }

        double best = double.MaxValue;
        for (int i = 0; i < f.V.Length; i++)
        {
            (double X, double Y, double Z) a = f.V[i], b = f.V[(i + 1) % f.V.Length];
            double dx = b.X - a.X, dy = b.Y - a.Y, length = (dx * dx) + (dy * dy);
            double t = length > 0 ? Math.Clamp((((x - a.X) * dx) + ((y - a.Y) * dy)) / length, 0, 1) : 0;
            double ex = a.X + (t * dx) - x, ey = a.Y + (t * dy) - y;
            best = Math.Min(best, Math.Sqrt((ex * ex) + (ey * ey)));
        }

        return best;
    }

    /// <summary>
    /// The solid the body ends inside of, if any: its centre more than 1 mm inside the solid's outline (widened by
    /// <paramref name="grown"/>: a start must be clear of every outline by the radius) with any of its height, feet to
    /// top, more than 1 mm into the solid's.
    /// </summary>
    private static string? Inside(World world, ResolveResult r, MoverBody body, double grown = 0)
    {
        (uint key, double x, double y) = Local(world, r);
        foreach ((uint other, List<Solid> solids) in world.Solids)
        {
            double ox = x - (((int)(other >> 8) - (int)(key >> 8)) * 192.0), oy = y - (((int)(other & 0xFF) - (int)(key & 0xFF)) * 192.0);
            foreach (Solid s in solids)
            {
                // The centre in the solid's frame (turned back about Z by its yaw).
                Quaternion q = s.Frame.Orientation;
                double yaw = 2 * Math.Atan2(q.Z, q.W);
                double px = ox - s.Frame.Origin.X, py = oy - s.Frame.Origin.Y;
                double lx = (px * Math.Cos(-yaw)) - (py * Math.Sin(-yaw)), ly = (px * Math.Sin(-yaw)) + (py * Math.Cos(-yaw));
                double bottom = s.Frame.Origin.Z, top = bottom + s.H, feet = r.Position.Z;
                if (Math.Abs(lx) < s.Hx + grown - 1e-3 && Math.Abs(ly) < s.Hy + grown - 1e-3 && feet < top - 1e-3 && feet + body.Height > bottom + 1e-3)
                {
                    return FormattableString.Invariant($"{s.Name} (local centre ({lx:F4}, {ly:F4}), half size {s.Hx} × {s.Hy}, Z {bottom} to {top})");
                }
            }
        }

        return null;
    }
}
