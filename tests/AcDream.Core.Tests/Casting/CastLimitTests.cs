using System.Numerics;
using AcDream.Core.Physics;
using AcDream.Testing;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Casting;

/// <summary>
/// The cast's limits as its documentation states them: it enters at most <see cref="PhysicsConstants.MaxCellVisits"/>
/// pieces and one that would need more ends where its last piece began (kind <see cref="SurfaceKind.None"/>), never
/// answering "met nothing" for a path it did not look at; a cast of zero length meets nothing.
/// </summary>
[Trait("Mutation", "SweptSphere")]
public class CastLimitTests
{
    public static TheoryData<string> Frames() => new() { "centred", "global" };

    /// <summary>A corridor of 40 cells 1 m long, east from x = 10 m, each joined to the next by a doorway; walls at its ends.</summary>
    private static (PhysicsEngine Engine, Vector3 Origin) Corridor(string frame)
    {
        const int count = 40;
        var cells = new List<CellSurface>();
        for (int i = 0; i < count; i++)
        {
            var b = new CellBuilder(0xA9B40100u + (uint)i, new Vector3(10f + i, 10f, 50f));
            b.Floor(0, 0, 1, 2, 0);
            b.Physics(TestData.Wall(0, 0, 1, 0, 0, 3));
            b.Physics(TestData.Wall(1, 2, 0, 2, 0, 3));
            var inside = new Vector3(0.5f, 1f, 1f);
            if (i > 0)
            {
                b.Portal((ushort)(0x0100 + i - 1), inside, new(0, 0, 0), new(0, 2, 0), new(0, 2, 2.5f), new(0, 0, 2.5f));
            }
            else
            {
                b.Physics(TestData.Wall(0, 2, 0, 0, 0, 3));
            }

            if (i < count - 1)
            {
                b.Portal((ushort)(0x0100 + i + 1), inside, new(1, 0, 0), new(1, 2, 0), new(1, 2, 2.5f), new(1, 0, 2.5f));
            }
            else
            {
                b.Physics(TestData.Wall(1, 0, 1, 2, 0, 3));
            }

            cells.Add(b.Build());
        }

        PhysicsEngine engine = frame == "global" ? new PhysicsEngine() : new PhysicsEngine(TestData.Holtburg);
        engine.AddLandblock(TestData.Holtburg, TestData.FlatTerrain(40f), cells);
        return (engine, engine.GetLandblockOrigin(TestData.Holtburg));
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_cast_through_more_cells_than_its_limit_ends_where_its_last_piece_began(string frame)
    {
        (PhysicsEngine engine, Vector3 o) = Corridor(frame);
        var from = new Vector3(10.5f, 11f, 51f);

        // Through 30 cells: within the limit, clear, ending in the 30th.
        CastHit within = engine.Cast(o + from, 0xA9B40100u, o + new Vector3(39.5f, 11f, 51f), new CastOptions(0f));
        within.Hit.Should().BeFalse($"{frame}: {within}");
        within.CellId.Should().Be(0xA9B4011Du, $"{frame}: {within}");

        // Through all 40: the 33rd piece is one too many; the cast ends where it begins, at the doorway x = 42 m.
        CastHit beyond = engine.Cast(o + from, 0xA9B40100u, o + new Vector3(49.5f, 11f, 51f), new CastOptions(0f));
        beyond.Hit.Should().BeTrue($"{frame}: {beyond}");
        beyond.Kind.Should().Be(SurfaceKind.None, $"{frame}: {beyond}");
        beyond.CellId.Should().Be(0xA9B40120u, $"{frame}: {beyond}");
        (beyond.Position - o).X.Should().BeApproximately(42f, frame == "global" ? 4e-3f : 1e-4f, $"{frame}: {beyond}");
        beyond.Fraction.Should().BeApproximately(31.5f / 39f, 1e-6f, $"{frame}: {beyond}");
        beyond.Normal.X.Should().BeApproximately(-1f, 1e-6f, $"{frame}: pointing back along the cast: {beyond}");
    }

    [Theory]
    [MemberData(nameof(Frames))]
    public void A_cast_of_zero_length_meets_nothing_even_within_its_radius_of_a_wall(string frame)
    {
        (PhysicsEngine engine, Vector3 o) = Corridor(frame);
        Vector3 at = o + new Vector3(10.5f, 10.1f, 51f); // 0.1 m from cell 0's south wall

        CastHit hit = engine.Cast(at, 0xA9B40100u, at, new CastOptions(0.3f));

        hit.Hit.Should().BeFalse($"{frame}: {hit}");
        hit.Fraction.Should().Be(1f, $"{frame}: {hit}");
        hit.Position.Should().Be(at, $"{frame}: {hit}");
        hit.CellId.Should().Be(0xA9B40100u, $"{frame}: {hit}");
    }
}
