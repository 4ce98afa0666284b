using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using Xunit.Abstractions;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// A <c>Resolve</c> with a body allocates nothing in steady state: indoors sliding along a wall and
/// stopping in a corner, on the real Holtburg cells (walls gathered through portals), outdoors on
/// open ground and sliding along a building's wall from outside. Each scenario is checked to be what
/// it claims (its outcomes) in a warm-up pass, then a second pass is counted with
/// <see cref="GC.GetAllocatedBytesForCurrentThread"/>.
/// </summary>
public class BodyAllocationTests(ITestOutputHelper output)
{
    private const float Step = 0.5f;
    private const int Calls = 5000;
    private static readonly MovementOptions BodyAlone = new() { Body = MoverBody.Player };

    /// <summary>
    /// Holtburg on flat terrain at 50 m with one 10 × 10 m room (cell-local 0..10) at landblock-local
    /// (100, 100, 50): walls 3 m high, a 1 m doorway to the outdoors in the south wall.
    /// </summary>
    private static (PhysicsEngine Engine, uint Cell, Vector3 Corner) RoomOnOpenGround()
    {
        uint cell = (Holtburg & 0xFFFF0000u) | 0x0100;
        var b = new CellBuilder(cell, new Vector3(100, 100, 50));
        b.Floor(0, 0, 10, 10, 0);
        b.Physics(Wall(0, 0, 4.5f, 0, 0, 3)).Physics(Wall(5.5f, 0, 10, 0, 0, 3));
        b.Physics(Wall(10, 0, 10, 10, 0, 3)).Physics(Wall(10, 10, 0, 10, 0, 3)).Physics(Wall(0, 10, 0, 0, 0, 3));
        b.Portal(0xFFFF, new Vector3(5, 5, 1), new(4.5f, 0, 0), new(5.5f, 0, 0), new(5.5f, 0, 2.5f), new(4.5f, 0, 2.5f));
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(50f), [b.Build()]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);
        return (engine, cell, new Vector3(origin.X + 100, origin.Y + 100, 50));
    }

    [Fact]
    public void Resolve_WithABody_AllocatesNothing()
    {
        (PhysicsEngine room, uint roomCell, Vector3 corner) = RoomOnOpenGround();
        uint outdoorCell = (Holtburg & 0xFFFF0000u) | 0x0001;
        PhysicsEngine holtburg = new(Holtburg);
        holtburg.AddLandblock(Holtburg, FlatTerrain(94f), HoltburgCells.Surfaces());
        holtburg.AddLandblock(0xA9B3FFFFu, FlatTerrain(94f, 0xA9B3FFFFu), []);
        Vector3 holtburgOrigin = holtburg.GetLandblockOrigin(Holtburg);
        var floors = new List<(Vector3 Position, uint Cell)>(); // points on the real cells' floors, every 0.5 m
        foreach (CellSurface surface in HoltburgCells.Surfaces())
        {
            for (float x = 120f; x <= 170f; x += 0.5f)
            {
                for (float y = -5f; y <= 25f; y += 0.5f)
                {
                    if (surface.SampleFloorZ(x, y) is float z)
                    {
                        floors.Add((holtburgOrigin + new Vector3(x, y, z), surface.CellId));
                    }
                }
            }
        }

        floors.Should().HaveCountGreaterThan(500);

        var scenarios = new (string Name, Func<int, ResolveResult> Call, ResolveOutcome[] Expected)[]
        {
            // Inside the room, 0.6 m off the east wall (x = 10), moving diagonally into it: a slide.
            ("indoor slide along a wall", i => room.Resolve(corner + new Vector3(9.4f, 2f + (i % 50 * 0.1f), 0), roomCell, new Vector3(0.3f, 0.2f, 0), Step, BodyAlone), [ResolveOutcome.Slid]),

            // Into the north-east corner from 0.7 m off both walls, 2 m: contact, slide, stop in the corner.
            ("indoor 2 m into a corner", i => room.Resolve(corner + new Vector3(9.3f, 9.3f - (i % 5 * 0.1f), 0), roomCell, new Vector3(1.6f, 1.2f, 0), Step, MovementOptions.Player), [ResolveOutcome.Slid, ResolveOutcome.Wall]),

            // Outside the room, 0.6 m east of its east wall, moving west into it and north: a slide outdoors.
            ("outdoor slide along a building", i => room.Resolve(corner + new Vector3(10.6f, 2f + (i % 50 * 0.1f), 0), outdoorCell, new Vector3(-0.3f, 0.2f, 0), Step, BodyAlone), [ResolveOutcome.Slid]),

            // Open ground far from the room: the point move.
            ("outdoor open ground", i => room.Resolve(corner + new Vector3(-60f + (i % 50 * 0.3f), -40f, 0), outdoorCell, new Vector3(0.2f, 0.15f, 0), Step, MovementOptions.Player), [ResolveOutcome.Moved]),

            // The real cells' floors, 0.1 to 2.4 m moves in eight directions with the player's options
            // (walls gathered through portals; some starts overlap a wall, as a teleported mover might).
            ("real Holtburg cells", i => Real(holtburg, floors[(i * 7919) % floors.Count], i), []),

            // The same with what each move met (the report overload).
            ("real Holtburg cells, with the report", i => Reported(holtburg, floors[(i * 7919) % floors.Count], i), []),
            ("indoor slide along a wall, with the report", i => room.Resolve(corner + new Vector3(9.4f, 2f + (i % 50 * 0.1f), 0), roomCell, new Vector3(0.3f, 0.2f, 0), Step, BodyAlone, out _), [ResolveOutcome.Slid]),

            // The body in the air (vertical motion): rising and falling in the real cells, 0.5 m over their floors.
            ("real Holtburg cells, in the air", i => Air(holtburg, floors[(i * 7919) % floors.Count], i), []),
        };

        foreach ((string name, Func<int, ResolveResult> call, ResolveOutcome[] expected) in scenarios)
        {
            // Warm-up: one full pass (JIT tiering, on-stack replacement), checking the outcomes.
            var outcomes = new SortedDictionary<ResolveOutcome, int>();
            for (int i = 0; i < Calls; i++)
            {
                ResolveResult r = call(i);
                outcomes[r.Outcome] = outcomes.GetValueOrDefault(r.Outcome) + 1;
                if (expected.Length > 0)
                {
                    expected.Should().Contain(r.Outcome, $"{name}, call {i}: {r}");
                }
            }

            // Then up to three counted passes: a per-call allocation shows in every pass; the runtime's
            // own one-time work (a late tier-up, seen once in a full-suite run on a loaded machine, as in
            // MovementOptionsTests) in one at most, so the quietest pass must be 0 B.
            float sink = Run(call);
            var passes = new List<long>();
            for (int pass = 0; pass < 3 && (passes.Count == 0 || passes[^1] != 0); pass++)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                sink += Run(call);
                passes.Add(GC.GetAllocatedBytesForCurrentThread() - before);
            }

            output.WriteLine($"{name}: {string.Join(", ", passes)} B over {Calls} resolves per pass; outcomes {string.Join(", ", outcomes.Select(kv => $"{kv.Key} {kv.Value}"))} (sink {sink})");
            passes.Min().Should().Be(0, $"{Calls} body resolves ({name}) allocated {string.Join(", ", passes)} bytes in successive passes");
        }
    }

    private static ResolveResult Air(PhysicsEngine engine, (Vector3 Position, uint Cell) start, int i)
    {
        float angle = i % 8 * MathF.PI / 4f, length = 0.1f + (i % 4 * 0.1f);
        float dz = i % 3 == 0 ? 0.3f : -0.4f * (i % 3);
        return engine.Resolve(start.Position + new Vector3(0f, 0f, 0.5f), start.Cell, new Vector3(length * MathF.Cos(angle), length * MathF.Sin(angle), dz), Step, MovementOptions.Player);
    }

    private static ResolveResult Real(PhysicsEngine engine, (Vector3 Position, uint Cell) start, int i)
    {
        float angle = i % 8 * MathF.PI / 4f, length = 0.1f + (i % 9 * 0.3f);
        return engine.Resolve(start.Position, start.Cell, new Vector3(length * MathF.Cos(angle), length * MathF.Sin(angle), 0), Step, MovementOptions.Player);
    }

    private static ResolveResult Reported(PhysicsEngine engine, (Vector3 Position, uint Cell) start, int i)
    {
        float angle = i % 8 * MathF.PI / 4f, length = 0.1f + (i % 9 * 0.3f);
        ResolveResult r = engine.Resolve(start.Position, start.Cell, new Vector3(length * MathF.Cos(angle), length * MathF.Sin(angle), 0), Step, MovementOptions.Player, out MoveReport report);
        return r with { CellId = r.CellId ^ report.Floor.Id ^ report.Wall.Id }; // the report read, so it is not optimised away
    }

    private static float Run(Func<int, ResolveResult> call)
    {
        float sink = 0f;
        for (int i = 0; i < Calls; i++)
        {
            sink += call(i).Position.Z;
        }

        return sink;
    }
}
