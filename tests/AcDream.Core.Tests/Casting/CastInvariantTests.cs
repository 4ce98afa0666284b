using System.Numerics;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using AcDream.Core.Tests.Moving;
using AcDream.Core.Tests.Robustness;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Testing.CastReference;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// What every answer keeps, in both world frames: a miss is the end with fraction 1; a contact's centre is its point
/// plus the radius along a unit normal, and lies on the segment at its fraction; the same call gives the same bits; and
/// each filter changes the answer exactly as stated (as if what it passes were not there) and nothing else (an id passes
/// a registered mover only, not an object by its model's id).
/// </summary>
public class CastInvariantTests(ITestOutputHelper output)
{
    /// <summary>Every field of an answer as bits: equal only if the answers are identical bit for bit.</summary>
    private static string Bits(CastHit h) => FormattableString.Invariant(
        $"{h.Hit} {BitConverter.SingleToInt32Bits(h.Fraction):X8} {Bits(h.Position)} {Bits(h.Point)} {Bits(h.Normal)} {h.Kind} {h.Id:X8} {h.CellId:X8}");

    private static string Bits(Vector3 v) =>
        FormattableString.Invariant($"{BitConverter.SingleToInt32Bits(v.X):X8}/{BitConverter.SingleToInt32Bits(v.Y):X8}/{BitConverter.SingleToInt32Bits(v.Z):X8}");

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Every_answer_keeps_its_invariants_and_repeats_bit_for_bit(string frame)
    {
        // Holtburg with the cellar stairs, the west door (closed) and a creature in the yard; casts from the rooms, the
        // cellar and the yard, of every length to 60 m, with radii 0–1 m.
        CastScene scene = CastWorlds.Holtburg(frame, terrain: true);
        PhysicsEngine engine = scene.Engine;
        (GfxObj slab, Vector3 origin, Quaternion orientation) = CastWorlds.WestDoor();
        engine.Movers.Add(ObjectPlacements.CottageWestDoor, new MoverShape(slab), engine.ToWorld(TestData.Holtburg, origin), ObjectPlacements.CottageWestDoorCell, orientation, MoverState.Door);
        engine.Movers.Add(2, MoverKit.Human, scene.World(132, 6, 94), 0xA9B40029, Quaternion.Identity, MoverState.Creature);
        engine.Movers.Commit();
        (uint Cell, V3 Lo, V3 Hi)[] starts =
        [
            (0xA9B40143, new V3(137.2, 4.4, 94.5), new V3(141.6, 12.6, 96.3)),
            (0xA9B40147, new V3(137.2, -0.6, 91.5), new V3(140.2, 11.0, 93.3)),
            (0, new V3(100, 0, 94.5), new V3(180, 60, 110)),
        ];
        var random = new Random(61);
        var calls = new List<(Vector3 From, uint Cell, Vector3 To, float Radius, CastHit Hit)>();
        int hits = 0;
        for (int n = 0; n < 3000; n++)
        {
            (uint cell, V3 lo, V3 hi) = starts[n % starts.Length];
            var start = new V3(lo.X + (random.NextDouble() * (hi.X - lo.X)), lo.Y + (random.NextDouble() * (hi.Y - lo.Y)), lo.Z + (random.NextDouble() * (hi.Z - lo.Z)));
            V3 move = new V3(random.NextDouble() - 0.5, random.NextDouble() - 0.5, random.NextDouble() - 0.6) * (random.NextDouble() * 120);
            float r = n % 4 == 0 ? 0f : (float)random.NextDouble();
            Vector3 from = scene.World(start), delta = scene.World(start + move) - from, to = from + delta; // the end: start plus delta, in floats
            CastHit hit = engine.Cast(new CastRequest(from, cell, delta) { Options = new CastOptions(r) });
            string what = $"case {n} [{frame}] from {from} in 0x{cell:X8} to {to}, r {r}: {hit}";
            if (!hit.Hit)
            {
                (hit.Fraction, hit.Position, hit.Point, hit.Normal, hit.Kind, hit.Id).Should().Be((1f, to, to, Vector3.Zero, SurfaceKind.None, 0u), what);
            }
            else
            {
                hits++;
                hit.Fraction.Should().BeInRange(0f, 1f, what);
                Math.Abs(hit.Normal.Length() - 1).Should().BeLessThan(1e-6f, what);
                (hit.Kind == SurfaceKind.None).Should().Be(hit.Id == 0, $"an id names what was met, and only then: {what}");

                // |Position − Point| is the radius: exactly in the centred frame (within 1e-5 m); in the global frame both
                // are rounded to the world's float spacing, 2–4 mm here, and so is their difference.
                double rounding = scene.Global ? 2 * Math.Max(CastScene.HalfSpacing(hit.Position), CastScene.HalfSpacing(hit.Point)) : 0;
                Math.Abs((scene.Local(hit.Position) - scene.Local(hit.Point)).Length - r).Should().BeLessThanOrEqualTo(1e-5 + rounding, what);

                // The centre is on the segment at the fraction.
                V3 a = scene.Local(from), b = scene.Local(to);
                double along = ((a + ((b - a) * hit.Fraction)) - scene.Local(hit.Position)).Length;
                along.Should().BeLessThanOrEqualTo(1e-4 + (1e-7 * (b - a).Length) + CastScene.HalfSpacing(hit.Position), what);
            }

            calls.Add((from, cell, to, r, hit));
        }

        // The same calls again, in another order: the same bits.
        foreach ((Vector3 from, uint cell, Vector3 to, float r, CastHit hit) in calls.AsEnumerable().Reverse())
        {
            Bits(engine.Cast(from, cell, to, new CastOptions(r))).Should().Be(Bits(hit), $"from {from} in 0x{cell:X8} to {to}, r {r}");
        }

        output.WriteLine($"[{frame}] {calls.Count} casts, {hits} contacts: invariants held, and every one repeated bit for bit");
        hits.Should().BeGreaterThan(1000);
    }

    /// <summary>
    /// A field on flat ground at 50 m (landblock 0x7A3B): a creature (2), an Ethereal creature (3), a player (4), a closed
    /// door (9) and a tree (an object's cylinder, Setup 0x02000001) around (96, 96), each of them left out as asked.
    /// </summary>
    private static PhysicsEngine Field(string frame, uint[] without, bool tree = true)
    {
        const uint landblock = MoverSmokeTests.Landblock, outdoor = MoverSmokeTests.Outdoor;
        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(landblock);
        List<ObjectSurface> objects = [];
        if (tree)
        {
            (Setup setup, Dictionary<uint, GfxObj> parts) = ObjectKit.Tree();
            objects.Add(new ObjectSurface(setup, parts, ObjectKit.At(new Vector3(96, 96, 50), 0f), 0));
        }

        engine.AddLandblock(landblock, TestData.FlatTerrain(50f, landblock), [], objects);
        Vector3 At(float x, float y) => engine.ToWorld(landblock, new Vector3(x, y, 50));
        (uint Id, MoverShape Shape, Vector3 Position, Quaternion Turn, MoverState State)[] movers =
        [
            (2, MoverKit.Human, At(92, 96), Quaternion.Identity, MoverState.Creature),
            (3, MoverKit.Human, At(96, 92), Quaternion.Identity, MoverState.Creature with { Physics = PhysicsStateFlags.Ethereal }),
            (4, MoverKit.Human, At(96, 100), Quaternion.Identity, MoverState.Player),
            (9, new MoverShape(MoverReference.SlabModel(1.2f, 2.2f)), At(100, 96), MoverReference.Yaw(0.7), MoverState.Door),
        ];
        foreach ((uint id, MoverShape shape, Vector3 position, Quaternion turn, MoverState state) in movers)
        {
            if (!without.Contains(id))
            {
                engine.Movers.Add(id, shape, position, outdoor, turn, state);
            }
        }

        engine.Movers.Commit();
        return engine;
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void Each_filter_passes_exactly_what_it_says_and_changes_nothing_else(string frame)
    {
        // Each filtered answer is, bit for bit, the unfiltered answer of the same field without what the filter passes.
        PhysicsEngine full = Field(frame, []);
        (string Name, CastOptions Options, uint Ignore, PhysicsEngine Without)[] filters =
        [
            ("ignore creatures", new CastOptions(0, CastFilter.IgnoreCreatures), 0, Field(frame, [2, 3, 4])),
            ("solid only", new CastOptions(0, CastFilter.SolidOnly), 0, Field(frame, [3])),
            ("both", new CastOptions(0, CastFilter.IgnoreCreatures | CastFilter.SolidOnly), 0, Field(frame, [2, 3, 4])),
            ("ignore the creature 2", new CastOptions(0), 2, Field(frame, [2])),
            ("ignore the Ethereal creature 3", new CastOptions(0), 3, Field(frame, [3])),
            ("ignore the door 9", new CastOptions(0), 9, Field(frame, [9])),
            ("ignore an id not there", new CastOptions(0), 77, full),
            ("ignore the tree's Setup id (an object's, not a mover's)", new CastOptions(0), 0x02000001, full),
        ];
        Vector3 centre = full.ToWorld(MoverSmokeTests.Landblock, new Vector3(96, 96, 50));
        var random = new Random(62);
        var changed = new int[filters.Length];
        int casts = 0;
        for (int n = 0; n < 1500; n++)
        {
            // From around the field through it: most casts pass near one or more of the five.
            double a = random.NextDouble() * 2 * Math.PI, b = a + Math.PI + ((random.NextDouble() - 0.5) * 0.8);
            float r = n % 3 == 0 ? 0f : (float)(random.NextDouble() * 0.6);
            Vector3 from = centre + new Vector3((float)(Math.Cos(a) * 8), (float)(Math.Sin(a) * 8), 0.2f + r + (float)(random.NextDouble() * 2.5));
            Vector3 to = centre + new Vector3((float)(Math.Cos(b) * 8), (float)(Math.Sin(b) * 8), 0.2f + r + (float)(random.NextDouble() * 2.5));
            CastHit plain = full.Cast(from, 0, to, new CastOptions(r));
            for (int f = 0; f < filters.Length; f++)
            {
                (string name, CastOptions options, uint ignore, PhysicsEngine without) = filters[f];
                CastHit filtered = full.Cast(from, 0, to, options with { Radius = r }, ignore);
                CastHit expected = without.Cast(from, 0, to, new CastOptions(r));
                Bits(filtered).Should().Be(Bits(expected), $"{name}, case {n}: from {from} to {to}, r {r}: filtered {filtered}; without it {expected}; unfiltered {plain}");
                changed[f] += Bits(filtered) == Bits(plain) ? 0 : 1;
            }

            casts++;
        }

        output.WriteLine($"[{frame}] {casts} casts; answers changed by each filter: {string.Join(", ", filters.Select((f, i) => $"{f.Name} {changed[i]}"))}");
        for (int f = 0; f < filters.Length - 2; f++)
        {
            changed[f].Should().BeGreaterThan(20, $"{filters[f].Name} passes something on many of the casts");
        }

        changed[^2].Should().Be(0, "an id that names nothing changes nothing");
        changed[^1].Should().Be(0, "an id passes a mover only: an object is not passed by its model's id");
    }

    [Theory]
    [MemberData(nameof(CastWorlds.Frames), MemberType = typeof(CastWorlds))]
    public void A_sphere_starting_overlapping_a_surface_stops_at_once_moving_into_it_and_is_free_of_it_moving_away_or_along(string frame)
    {
        // A wall (x = 96 of the field's frame, y 90–102, z 50–53), the ground at 50 m and a creature (2, at (92, 96)),
        // each overlapped by 0.2 m of a 0.3 m sphere at the start.
        PhysicsEngine engine = Field(frame, [3, 4, 9], tree: false);
        GfxObj wall = DeterminismWalk.AddPhysicsPolygons(new GfxObj { Id = 0x01FF0C01, Flags = GfxObjFlags.HasPhysics }, [TestData.Wall(96, 90, 96, 102, 50, 53)]);
        engine.AddLandblock(MoverSmokeTests.Landblock, TestData.FlatTerrain(50f, MoverSmokeTests.Landblock), [], [new ObjectSurface(wall, new Frame(), 0)]);
        Vector3 At(float x, float y, float z) => engine.ToWorld(MoverSmokeTests.Landblock, new Vector3(x, y, z));
        const float r = 0.3f;
        (string What, Vector3 From, Vector3 Into, Vector3 Away, Vector3 Along, SurfaceKind Kind)[] cases =
        [
            ("the wall", At(95.9f, 95, 51.5f), new Vector3(1, 0.2f, 0), new Vector3(-1, 0.3f, 0.1f), new Vector3(0, 1, 0), SurfaceKind.ObjectWall),
            ("the ground", At(100, 99, 50.1f), new Vector3(0.3f, 0, -1), new Vector3(0.3f, 0.2f, 1), new Vector3(1, 0.5f, 0), SurfaceKind.Terrain),
            ("the creature", At(92, 96.58f, 51), new Vector3(0.1f, -1, 0), new Vector3(0, 1, 0.2f), new Vector3(1, 0, 0), SurfaceKind.Mover),
        ];
        foreach ((string what, Vector3 from, Vector3 into, Vector3 away, Vector3 along, SurfaceKind kind) in cases)
        {
            CastHit stopped = engine.Cast(from, 0, from + into, new CastOptions(r));
            (stopped.Hit, stopped.Fraction, stopped.Position).Should().Be((true, 0f, from), $"{what}, moving into it: {stopped}");
            stopped.Kind.Should().Be(kind, $"{what}: {stopped}");

            CastHit leaving = engine.Cast(from, 0, from + away, new CastOptions(r));
            leaving.Hit.Should().BeFalse($"{what}, moving away: {leaving}");
            CastHit sliding = engine.Cast(from, 0, from + along, new CastOptions(r));
            sliding.Hit.Should().BeFalse($"{what}, moving along it: {sliding}");
            output.WriteLine($"[{frame}] {what}: into {stopped}; away {leaving.Hit}; along {sliding.Hit}");
        }
    }
}
