using System.Numerics;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;
using Xunit.Abstractions;

namespace AcDream.Core.Tests.Robustness;

/// <summary>
/// A cell's open floor (<see cref="OpenFloor"/>) lets the body's planner skip its sweep only where the sweep would
/// touch nothing: whenever it says open, no wall of the cell or of an object standing in it has bounds meeting the
/// box within the band, and no portal's bounds meet the wall set's box (checked wall by wall, on every real Holtburg
/// cell, over random boxes and bands).
/// </summary>
public sealed class OpenFloorTests(ITestOutputHelper output)
{
    [Fact]
    public void Open_floor_is_said_only_where_no_wall_or_portal_is_near()
    {
        var random = new Random(18);
        int open = 0, closed = 0;
        foreach (CellSurface cell in HoltburgCells.Surfaces())
        {
            OpenFloor? floor = OpenFloor.Build(cell);
            if (floor is null)
            {
                continue;
            }

            for (int i = 0; i < 4000; i++)
            {
                var centre = new Vector2(
                    cell.FloorMin.X + (random.NextSingle() * (cell.FloorMax.X - cell.FloorMin.X)),
                    cell.FloorMin.Y + (random.NextSingle() * (cell.FloorMax.Y - cell.FloorMin.Y)));
                Vector2 half = new(0.2f + (random.NextSingle() * 1.2f), 0.2f + (random.NextSingle() * 1.2f));
                float reach = half.X + (random.NextSingle() * 0.6f);
                float zLow = FloorZ(cell, centre) - 2f + (random.NextSingle() * 4f);
                float zHigh = zLow + 0.2f + (random.NextSingle() * 2f);
                bool said = floor.IsOpen(centre - half, centre + half, zLow, zHigh, centre - new Vector2(reach), centre + new Vector2(reach));
                if (!said)
                {
                    closed++;
                    continue;
                }

                open++;
                string what = $"cell 0x{cell.CellId:X8}, box {centre - half}–{centre + half}, band {zLow}–{zHigh}, reach {reach}";
                foreach (CellWalls walls in new[] { cell.Walls }.Concat(cell.Objects.Select(o => o.Walls)))
                {
                    foreach (WallPolygon w in walls.Polygons)
                    {
                        bool meets = w.Min.X <= centre.X + half.X && w.Max.X >= centre.X - half.X && w.Min.Y <= centre.Y + half.Y && w.Max.Y >= centre.Y - half.Y
                            && w.ZMax > zLow && w.ZMin < zHigh;
                        meets.Should().BeFalse($"open floor, yet a wall ({w.Min}–{w.Max}, z {w.ZMin}–{w.ZMax}) meets {what}");
                    }
                }

                foreach (PortalShape p in cell.PortalShapes)
                {
                    bool meets = p.BoundsMin.X <= centre.X + reach && p.BoundsMax.X >= centre.X - reach && p.BoundsMin.Y <= centre.Y + reach && p.BoundsMax.Y >= centre.Y - reach;
                    meets.Should().BeFalse($"open floor, yet a portal ({p.BoundsMin}–{p.BoundsMax}) meets {what}");
                }
            }
        }

        output.WriteLine($"open {open}, not open {closed}");
        open.Should().BeGreaterThan(1000, "the test must see open floor to test it");
        closed.Should().BeGreaterThan(1000);
    }

    private static float FloorZ(CellSurface cell, Vector2 p) => cell.SampleFloorZ(p.X, p.Y) ?? cell.GetFloorTriangles()[0].A.Z;
}

/// <summary>The float spacing the body's skin is built from is <c>MathF.BitIncrement(x) − x</c>, bit for bit, at every scale.</summary>
public sealed class SpacingTests
{
    [Fact]
    public void Spacing_is_the_bit_increment_at_every_scale()
    {
        var random = new Random(7);
        var cases = new List<float> { 0f, float.Epsilon, 1e-40f, 1e-38f, 1.1754944e-38f, 1e-30f, 0.48f, 1f, 2f, 192f, 65535f, 3.9e6f, 1e20f, float.MaxValue, float.MaxValue / 2f, float.PositiveInfinity };
        for (int i = 0; i < 100_000; i++)
        {
            cases.Add(BitConverter.Int32BitsToSingle(random.Next(0, 0x7F800001)));
        }

        foreach (float x in cases)
        {
            float want = MathF.BitIncrement(x) - x, got = Geometry.Spacing(x);
            BitConverter.SingleToInt32Bits(got).Should().Be(BitConverter.SingleToInt32Bits(want), $"x = {x:R} (0x{BitConverter.SingleToInt32Bits(x):X8}): {got:R} against {want:R}");
        }
    }
}
