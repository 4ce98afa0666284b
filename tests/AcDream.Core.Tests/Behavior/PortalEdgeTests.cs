using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using static AcDream.Core.Tests.TestData;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The portal search at the edges of its openings: the neighbour nearest the feet taken when no portal decides, a
/// climb through a ceiling opening that does not fall on through an opening far below the room above, an opening
/// overhead met within the edge tolerance of its outline from each side, and a floor opening exactly a step below
/// the feet of a walking mover. Positions in the frame centred on the landblock, where a tenth of a millimetre is
/// representable.
/// </summary>
[Trait("Mutation", "PortalTraversal")]
public class PortalEdgeTests
{
    private const float Step = 0.6f;
    private const float GroundZ = 94f;

    /// <summary>
    /// A room (0x0101) whose only portals are floor openings far below, away from the move, to two cells beside it
    /// whose floors overlap east of it: 0x0100 half a metre below the feet, 0x0102 a tenth of a metre above them.
    /// With no doorway crossed and no opening under the end, the neighbour whose floor is nearer the feet takes the
    /// mover, whichever is listed first.
    /// </summary>
    [Fact]
    public void With_no_portal_deciding_the_neighbour_whose_floor_is_nearest_the_feet_takes_the_mover()
    {
        foreach (bool lowerListedFirst in new[] { true, false })
        {
            Vector3[] low = Square(100f, 100f, 101f, 101f, GroundZ - 10f), lower = Square(101f, 100f, 102f, 101f, GroundZ - 10f);
            var room = new CellBuilder(0xA9B40101u).Floor(100f, 100f, 104f, 104f, GroundZ);
            room = lowerListedFirst
                ? room.Portal(0x0100, new Vector3(100.5f, 100.5f, GroundZ), low).Portal(0x0102, new Vector3(101.5f, 100.5f, GroundZ), lower)
                : room.Portal(0x0102, new Vector3(101.5f, 100.5f, GroundZ), lower).Portal(0x0100, new Vector3(100.5f, 100.5f, GroundZ), low);
            CellSurface below = new CellBuilder(0xA9B40100u).Floor(104f, 100f, 108f, 104f, GroundZ - 0.5f)
                .Portal(0x0101, new Vector3(100.5f, 100.5f, GroundZ - 11f), low).Build();
            CellSurface above = new CellBuilder(0xA9B40102u).Floor(104f, 102f, 108f, 106f, GroundZ + 0.1f)
                .Portal(0x0101, new Vector3(101.5f, 100.5f, GroundZ - 11f), lower).Build();
            var engine = new PhysicsEngine(Holtburg);
            engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [below, room.Build(), above]);
            Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(103f, 103f, GroundZ);

            ResolveResult r = engine.Resolve(start, 0xA9B40101u, new Vector3(2f, 0f, 0f), Step);
            (r.Outcome, r.CellId, r.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40102u, GroundZ + 0.1f), $"the floor 0.1 m above the feet, not the one 0.5 m below ({(lowerListedFirst ? "listed second" : "listed first")}): {r}");
        }
    }

    /// <summary>
    /// A cellar (0x0100, floor at 94 m) with an opening in its ceiling (0.5 m above its floor) into a room (0x0101)
    /// whose floor beside it is 0.5 m up, and beyond the opening, in the room, an opening 10 m below the room's floor
    /// into a shaft (0x0102) with its floor at 80 m. A mover climbing through the ceiling opening and on over the
    /// shaft's opening walks: it does not fall 14 m down the shaft; nothing else takes it there, so it is refused.
    /// Ending beside the shaft's opening on the room's floor, it stands there.
    /// </summary>
    [Fact]
    public void A_mover_climbing_through_a_ceiling_opening_does_not_fall_through_an_opening_far_below_the_room_above()
    {
        Vector3[] up = Square(100f, 100f, 104f, 102f, GroundZ + 0.5f), shaftTop = Square(104f, 100f, 106f, 102f, GroundZ - 9.5f);
        CellSurface cellar = new CellBuilder(0xA9B40100u).Floor(94f, 98f, 104f, 104f, GroundZ)
            .Portal(0x0101, new Vector3(102f, 101f, GroundZ), up).Build();
        CellSurface room = new CellBuilder(0xA9B40101u).Floor(94f, 98f, 100f, 104f, GroundZ + 0.5f).Floor(106f, 98f, 110f, 104f, GroundZ + 0.5f)
            .Floor(104f, 102f, 106f, 104f, GroundZ + 0.5f)
            .Portal(0x0100, new Vector3(102f, 101f, GroundZ + 1.5f), up)
            .Portal(0x0102, new Vector3(105f, 101f, GroundZ + 1f), shaftTop).Build();
        CellSurface shaft = new CellBuilder(0xA9B40102u).Floor(104f, 100f, 106f, 102f, 80f)
            .Portal(0x0101, new Vector3(105f, 101f, 82f), shaftTop).Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 30f), [cellar, room, shaft]);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(101f, 101f, GroundZ);

        ResolveResult over = engine.Resolve(start, 0xA9B40100u, new Vector3(4f, 0f, 0f), Step);
        (over.IsRefused, over.Position, over.CellId).Should().Be((true, start, 0xA9B40100u), $"climbed through the ceiling opening onto an opening 10 m below: {over}");

        ResolveResult beside = engine.Resolve(start, 0xA9B40100u, new Vector3(4f, 2f, 0f), Step);
        (beside.Outcome, beside.CellId, beside.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40101u, GroundZ + 0.5f), $"climbed onto the room's floor beside the shaft's opening: {beside}");
    }

    /// <summary>
    /// A cellar (floor 94 m) under a room (floor 95 m) with an opening in its ceiling over x 100..104, y 100..102, the
    /// feet at 94.75 m (the room's floor 0.25 m above, the cellar's 0.75 m below). A move wholly beside the opening on
    /// each side, ending a tenth of a millimetre short of its edge (within the edge tolerance), passes under it and
    /// lands on the room's floor; ending a millimetre short, it does not, and lands on the cellar's floor.
    /// </summary>
    [Fact]
    public void A_move_ending_within_the_edge_tolerance_of_a_ceiling_opening_on_any_side_climbs_through_it()
    {
        const float Feet = GroundZ + 0.75f;
        Vector3[] opening = Square(100f, 100f, 104f, 102f, GroundZ + 1f);
        CellSurface cellar = new CellBuilder(0xA9B40100u).Floor(90f, 94f, 114f, 108f, GroundZ)
            .Portal(0x0101, new Vector3(102f, 101f, GroundZ + 0.5f), opening).Build();
        CellSurface room = new CellBuilder(0xA9B40101u)
            .Floor(90f, 94f, 100f, 108f, GroundZ + 1f).Floor(104f, 94f, 114f, 108f, GroundZ + 1f)
            .Floor(100f, 94f, 104f, 100f, GroundZ + 1f).Floor(100f, 102f, 104f, 108f, GroundZ + 1f)
            .Portal(0x0100, new Vector3(102f, 101f, GroundZ + 2f), opening).Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [cellar, room]);
        Vector3 origin = engine.GetLandblockOrigin(Holtburg);

        var sides = new (string Side, Vector2 Start, Vector2 Toward)[]
        {
            ("west", new(99f, 101f), new(1f, 0f)),
            ("east", new(105f, 101f), new(-1f, 0f)),
            ("south", new(102f, 99f), new(0f, 1f)),
            ("north", new(102f, 103f), new(0f, -1f)),
        };
        foreach ((string side, Vector2 from, Vector2 toward) in sides)
        {
            Vector3 start = origin + new Vector3(from, Feet);
            ResolveResult within = engine.Resolve(start, 0xA9B40100u, new Vector3(toward * (1f - 0.0001f), 0f), Step);
            (within.Outcome, within.CellId, within.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40101u, GroundZ + 1f), $"{side}: 0.1 mm short of the opening's edge: {within}");
            ResolveResult shortOf = engine.Resolve(start, 0xA9B40100u, new Vector3(toward * (1f - 0.001f), 0f), Step);
            (shortOf.Outcome, shortOf.CellId, shortOf.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40100u, GroundZ), $"{side}: 1 mm short of the opening's edge: {shortOf}");
        }
    }

    /// <summary>
    /// A walking mover stepping off its floor (94 m) over an opening in the floor of the cell beside it, into a cell
    /// with no floor under the end whose own opening below leads to a bottom cell (floor at 92 m): with the opening
    /// exactly a step below the feet it passes through it and on down to the bottom; with the opening a centimetre
    /// deeper it does not pass it, and nothing else takes it: it is refused.
    /// </summary>
    [Fact]
    public void A_walking_mover_passes_a_floor_opening_exactly_a_step_below_its_feet_and_not_one_deeper()
    {
        foreach ((float depth, bool passes) in new[] { (Step, true), (Step + 0.01f, false) })
        {
            float openingZ = GroundZ - depth;
            Vector3[] hole = Square(102f, 100f, 104f, 102f, openingZ), foot = Square(102f, 100f, 104f, 102f, openingZ - 0.5f);
            CellSurface side = new CellBuilder(0xA9B40100u).Floor(98f, 100f, 102f, 102f, GroundZ)
                .Portal(0x0101, new Vector3(103f, 101f, GroundZ), hole).Build();
            CellSurface mid = new CellBuilder(0xA9B40101u)
                .Portal(0x0100, new Vector3(103f, 101f, openingZ - 0.25f), hole).Portal(0x0102, new Vector3(103f, 101f, openingZ - 0.25f), foot).Build();
            CellSurface bottom = new CellBuilder(0xA9B40102u).Floor(102f, 100f, 104f, 102f, 92f)
                .Portal(0x0101, new Vector3(103f, 101f, 92.2f), foot).Build();
            var engine = new PhysicsEngine(Holtburg);
            engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 30f), [side, mid, bottom]);
            Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(101.5f, 101f, GroundZ);

            ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(1f, 0f, 0f), Step);
            if (passes)
            {
                (r.Outcome, r.CellId, r.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40102u, 92f), $"the opening {depth} m below the feet: {r}");
            }
            else
            {
                (r.IsRefused, r.Position, r.CellId).Should().Be((true, start, 0xA9B40100u), $"the opening {depth} m below the feet: {r}");
            }
        }
    }
    /// <summary>
    /// Walking over an opening in the floor of the cell beside its own at exactly the step plus the edge tolerance
    /// below the feet (as the engine computes it in float: the feet chosen so that it is), into a cell with no floor
    /// whose own opening leads on down to a bottom cell (floor at 92 m), the mover passes through it and lands there.
    /// </summary>
    [Fact]
    public void A_walking_mover_passes_a_floor_opening_exactly_the_step_and_the_edge_tolerance_below_its_feet()
    {
        const float OpeningZ = 93.375f; // the mean of its four corners is exactly this height
        float feet = FeetWhere(OpeningZ, z => z - Step - PhysicsConstants.EdgeTolerance);
        Vector3[] hole = Square(102f, 100f, 104f, 102f, OpeningZ), foot = Square(102f, 100f, 104f, 102f, OpeningZ - 0.5f);
        CellSurface side = new CellBuilder(0xA9B40100u).Floor(98f, 100f, 102f, 102f, feet)
            .Portal(0x0101, new Vector3(103f, 101f, feet), hole).Build();
        CellSurface mid = new CellBuilder(0xA9B40101u)
            .Portal(0x0100, new Vector3(103f, 101f, OpeningZ - 0.25f), hole).Portal(0x0102, new Vector3(103f, 101f, OpeningZ - 0.25f), foot).Build();
        CellSurface bottom = new CellBuilder(0xA9B40102u).Floor(102f, 100f, 104f, 102f, 92f)
            .Portal(0x0101, new Vector3(103f, 101f, 92.2f), foot).Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 30f), [side, mid, bottom]);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(101.5f, 101f, feet);

        ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(1f, 0f, 0f), Step);
        (r.Outcome, r.CellId, r.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40102u, 92f), $"feet {feet}, the opening at {OpeningZ}: {r}");
    }

    /// <summary>
    /// A cellar (floor 94 m) whose ceiling opening and the room's floor around it are exactly the step plus the edge
    /// tolerance above the feet (as the engine computes it in float): a move from under the opening to beside it
    /// climbs through it to the room's floor (nearer the feet than the cellar's), which, the tolerance more than the
    /// step up, refuses the move as a step too high; it does not fall back to the cellar's floor.
    /// </summary>
    [Fact]
    public void A_ceiling_opening_exactly_the_step_and_the_edge_tolerance_above_the_feet_is_climbed()
    {
        const float OpeningZ = 95.375f;
        float feet = FeetWhere(OpeningZ, z => z + Step + PhysicsConstants.EdgeTolerance);
        Vector3[] opening = Square(100f, 100f, 104f, 102f, OpeningZ);
        CellSurface cellar = new CellBuilder(0xA9B40100u).Floor(90f, 94f, 114f, 108f, GroundZ)
            .Portal(0x0101, new Vector3(102f, 101f, GroundZ + 0.5f), opening).Build();
        CellSurface room = new CellBuilder(0xA9B40101u)
            .Floor(90f, 94f, 100f, 108f, OpeningZ).Floor(104f, 94f, 114f, 108f, OpeningZ)
            .Floor(100f, 94f, 104f, 100f, OpeningZ).Floor(100f, 102f, 104f, 108f, OpeningZ)
            .Portal(0x0100, new Vector3(102f, 101f, OpeningZ + 1f), opening).Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [cellar, room]);
        Vector3 start = engine.GetLandblockOrigin(Holtburg) + new Vector3(102f, 101f, feet);

        ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(3f, 0f, 0f), Step);
        (r.Outcome, r.Position, r.CellId).Should().Be((ResolveOutcome.StepTooHigh, start, 0xA9B40100u), $"feet {feet}, the opening at {OpeningZ}: {r}");
    }

    /// <summary>
    /// The cellar and room of <see cref="A_move_ending_within_the_edge_tolerance_of_a_ceiling_opening_on_any_side_climbs_through_it"/>:
    /// a move starting exactly the edge tolerance beside the opening (its bound less or plus the tolerance, as the engine
    /// computes it in float) and leaving it, on each side, starts under the opening and climbs through it onto the
    /// room's floor.
    /// </summary>
    [Fact]
    public void A_move_starting_exactly_the_edge_tolerance_beside_a_ceiling_opening_climbs_through_it()
    {
        const float Feet = GroundZ + 0.75f, Tol = PhysicsConstants.EdgeTolerance;
        Vector3[] opening = Square(100f, 100f, 104f, 102f, GroundZ + 1f);
        CellSurface cellar = new CellBuilder(0xA9B40100u).Floor(90f, 94f, 114f, 108f, GroundZ)
            .Portal(0x0101, new Vector3(102f, 101f, GroundZ + 0.5f), opening).Build();
        CellSurface room = new CellBuilder(0xA9B40101u)
            .Floor(90f, 94f, 100f, 108f, GroundZ + 1f).Floor(104f, 94f, 114f, 108f, GroundZ + 1f)
            .Floor(100f, 94f, 104f, 100f, GroundZ + 1f).Floor(100f, 102f, 104f, 108f, GroundZ + 1f)
            .Portal(0x0100, new Vector3(102f, 101f, GroundZ + 2f), opening).Build();
        var engine = new PhysicsEngine(Holtburg);
        engine.AddLandblock(Holtburg, FlatTerrain(GroundZ - 20f), [cellar, room]);

        float west = 100f, east = 104f, south = 100f, north = 102f;
        var sides = new (string Side, Vector2 Start, Vector2 Away)[]
        {
            ("west", new(west - Tol, 101f), new(-1f, 0f)),
            ("east", new(east + Tol, 101f), new(1f, 0f)),
            ("south", new(102f, south - Tol), new(0f, -1f)),
            ("north", new(102f, north + Tol), new(0f, 1f)),
        };
        foreach ((string side, Vector2 from, Vector2 away) in sides)
        {
            Vector3 start = engine.ToWorld(Holtburg, new Vector3(from, Feet));
            engine.ToLandblockLocal(Holtburg, start).Should().Be(new Vector3(from, Feet), $"{side}: the start is exactly where it is meant to be");
            ResolveResult r = engine.Resolve(start, 0xA9B40100u, new Vector3(away, 0f), Step);
            (r.Outcome, r.CellId, r.Position.Z).Should().Be((ResolveOutcome.Moved, 0xA9B40101u, GroundZ + 1f), $"{side}: {r}");
        }
    }

    /// <summary>The float feet height (near <paramref name="target"/> ∓ the step) at which <paramref name="reach"/> gives exactly <paramref name="target"/>.</summary>
    private static float FeetWhere(float target, Func<float, float> reach)
    {
        float guess = target - (reach(target) - target);
        int bits = BitConverter.SingleToInt32Bits(guess);
        for (int i = -256; i <= 256; i++)
        {
            float feet = BitConverter.Int32BitsToSingle(bits + i);
            if (reach(feet) == target)
            {
                return feet;
            }
        }

        throw new InvalidOperationException($"no feet height reaches exactly {target}");
    }
}
