using System.Numerics;
using System.Text;
using System.Text.Json;
using AcDream.App.Fixtures;
using AcDream.Core.Dat;
using AcDream.Core.Physics;
using FluentAssertions;
using Xunit;

namespace AcDream.Core.Tests.Behavior;

/// <summary>
/// The two cellar stairs of Holtburg (<see cref="ObjectPlacements.CellarStairs"/>): each cellar is reached
/// on foot by walking down its stair from the room above, walked along, and left by walking back up into
/// that room, with the player's step of 0.6 m: the point mover and the player's body, in the global and
/// the centred world frame.
/// </summary>
[Trait("Mutation", "ObjectQueries")]
[Trait("Mutation", "WallSet")]
[Trait("Mutation", "BodySweep")]
[Trait("Mutation", "PortalTraversal")]
public class CellarStairTests
{
    private const float Step = 0.6f;
    private const uint CottageRoom = 0xA9B40143; // the ground-floor room around the stair opening (shaft 0x0146)
    private const uint BuildingBRoom = 0xA9B40171; // the room around building B's opening (shaft 0x0175)

    /// <summary>The engine as a host registers the scene: the cells, the buildings, and the stairs as the cellars' static objects.</summary>
    private static PhysicsEngine Engine(string frame) => RealObjects.HoltburgWithCellarStairs(frame);

    /// <summary>A recorded ramp of <c>captured-walkables.json</c>: its vertices and plane, landblock-local.</summary>
    private sealed record Ramp(Vector3[] Vertices, Vector3 Normal, float D)
    {
        public float MinX => Vertices.Min(v => v.X);

        public float MaxX => Vertices.Max(v => v.X);

        public float MinY => Vertices.Min(v => v.Y);

        public float MaxY => Vertices.Max(v => v.Y);

        public bool IsOver(Vector3 p) => p.X >= MinX && p.X <= MaxX && p.Y >= MinY && p.Y <= MaxY;

        public double PlaneZ(Vector3 p) => -((Normal.X * (double)p.X) + (Normal.Y * (double)p.Y) + D) / Normal.Z;
    }

    private static Ramp Recorded(string id)
    {
        string path = Path.Combine(AppContext.BaseDirectory, "Fixtures", "objects", "captured-walkables.json");
        using JsonDocument document = JsonDocument.Parse(File.ReadAllText(path));
        JsonElement walkable = document.RootElement.GetProperty("walkables").EnumerateArray().Single(w => w.GetProperty("id").GetString() == id);
        static Vector3 V(JsonElement a) => new(a[0].GetSingle(), a[1].GetSingle(), a[2].GetSingle());
        return new Ramp(
            [.. walkable.GetProperty("vertices").EnumerateArray().Select(V)],
            V(walkable.GetProperty("normal")),
            walkable.GetProperty("d").GetSingle());
    }

    private static readonly Ramp CottageRamp = Recorded("issue98-cellar-ramp");
    private static readonly Ramp BuildingBRamp = Recorded("cellar-lip-ramp");

    public static TheoryData<string, string, bool> Walks()
    {
        var data = new TheoryData<string, string, bool>();
        foreach (string cellar in new[] { "cottage", "building B" })
        {
            foreach (string frame in new[] { "global", "centred" })
            {
                data.Add(cellar, frame, false);
                data.Add(cellar, frame, true);
            }
        }

        return data;
    }

    [Theory]
    [MemberData(nameof(Walks))]
    public void The_cellar_is_entered_down_its_stair_walked_and_left_up_into_the_room_above(string cellar, string frame, bool player) =>
        Walk(cellar, frame, player, cellar == "cottage" ? 141.3f : 153.92f);

    /// <summary>
    /// Lanes across each stair: the point mover near both edges; the body where it clears the walls beside
    /// the stair (nearer the cottage opening's west edge its head meets the 0.2 m slab edge of the room's
    /// floor, 0x0146's wall at x 140.5, z 93.8..94, as it climbs; nearer its east edge it meets the
    /// room's wall at x 142.1).
    /// </summary>
    public static TheoryData<string, float, bool> Lanes() => new()
    {
        { "cottage", 140.6f, false }, { "cottage", 142.0f, false }, { "cottage", 141.0f, true }, { "cottage", 141.6f, true },
        { "building B", 153.2f, false }, { "building B", 154.6f, false }, { "building B", 153.6f, true }, { "building B", 154.3f, true },
    };

    [Theory]
    [MemberData(nameof(Lanes))]
    public void The_stairs_are_walked_down_and_up_in_other_lanes_across_them(string cellar, float laneX, bool player) =>
        Walk(cellar, "centred", player, laneX);

    private static void Walk(string cellar, string frame, bool player, float laneX)
    {
        PhysicsEngine engine = Engine(frame);
        bool cottage = cellar == "cottage";
        Ramp ramp = cottage ? CottageRamp : BuildingBRamp;
        uint stairId = cottage ? ObjectPlacements.CottageCellarStair : ObjectPlacements.BuildingBCellarStair;
        uint cellarId = cottage ? ObjectPlacements.CottageCellar : ObjectPlacements.BuildingBCellar;
        uint room = cottage ? CottageRoom : BuildingBRoom;
        float cellarFloor = cottage ? 90.95f : 90.001f;

        // Cottage: from the room west of the opening, east onto the ramp's top (z above the cellar's
        // ceiling, 93.8, for y < 5.99), down it (+y) into the cellar, west along the cellar and back, up
        // the ramp and west into the room. Building B: from the room north of the opening, south (−y)
        // down the landing, ramp and tread to the cellar floor, east along the cellar and back, and up.
        int east = (int)MathF.Round((laneX - 139.6f) / 0.1f);
        (Vector3 start, (Vector2 Delta, int Frames)[] legs) = cottage
            ? (new Vector3(laneX - (0.1f * east), 5.9f, 94f), new (Vector2, int)[] { (new Vector2(0.1f, 0f), east), (new Vector2(0f, 0.1f), 42), (new Vector2(-0.1f, 0f), 20), (new Vector2(0.1f, 0f), 20), (new Vector2(0f, -0.1f), 42), (new Vector2(-0.1f, 0f), east) })
            : (new Vector3(laneX, 12f, 94f), new (Vector2, int)[] { (new Vector2(0f, -0.1f), 65), (new Vector2(0.1f, 0f), 40), (new Vector2(-0.1f, 0f), 40), (new Vector2(0f, 0.1f), 65) });

        MovementOptions options = player ? MovementOptions.Player : default;
        var at = new ResolveResult(engine.ToWorld(TestData.Holtburg, start), room, true);
        var trace = new StringBuilder();
        var cells = new List<uint> { room };
        int onRampDown = 0, onRampUp = 0, onCellarFloor = 0;
        double worstRamp = 0;
        for (int legIndex = 0; legIndex < legs.Length; legIndex++)
        {
            (Vector2 delta, int frames) = legs[legIndex];
            for (int i = 0; i < frames; i++)
            {
                ResolveResult before = at;
                at = player
                    ? engine.Resolve(at.Position, at.CellId, new Vector3(delta, 0f), Step, options)
                    : engine.Resolve(at.Position, at.CellId, new Vector3(delta, 0f), Step);
                Vector3 local = engine.ToLandblockLocal(TestData.Holtburg, at.Position);
                engine.TryGetGround(at.Position, at.CellId, Step, out float groundZ, out _, out uint objectId);
                trace.AppendLine($"leg {legIndex} frame {i}: local ({local.X:F4}, {local.Y:F4}, {local.Z:F5}) 0x{at.CellId:X8} ground {at.IsOnGround} {at.Outcome} on 0x{objectId:X8} at {groundZ:F5}");
                string why = $"{cellar}, {frame}, {(player ? "Player" : "point")}, lane x {laneX}, leg {legIndex} frame {i}: {before} → {at}\n{trace}";

                at.IsOnGround.Should().BeTrue(why);
                at.IsRefused.Should().BeFalse(why);

                ResolveResult again = player
                    ? engine.Resolve(at.Position, at.CellId, Vector3.Zero, Step, options)
                    : engine.Resolve(at.Position, at.CellId, Vector3.Zero, Step);
                (BitConverter.SingleToInt32Bits(again.Position.X), BitConverter.SingleToInt32Bits(again.Position.Y), BitConverter.SingleToInt32Bits(again.Position.Z), again.CellId, again.IsOnGround)
                    .Should().Be((BitConverter.SingleToInt32Bits(at.Position.X), BitConverter.SingleToInt32Bits(at.Position.Y), BitConverter.SingleToInt32Bits(at.Position.Z), at.CellId, at.IsOnGround), $"a zero-delta re-resolve returns the answer bit for bit: {again} vs {at} ({why})");

                if (at.CellId != cells[^1])
                {
                    cells.Add(at.CellId);
                }

                if (objectId == stairId && ramp.IsOver(local))
                {
                    double off = Math.Abs(local.Z - ramp.PlaneZ(local));
                    off.Should().BeLessThanOrEqualTo(1e-3, $"on the recorded ramp, z {local.Z} vs its plane {ramp.PlaneZ(local)} ({why})");
                    worstRamp = Math.Max(worstRamp, off);
                    if (legIndex == (cottage ? 1 : 0))
                    {
                        onRampDown++;
                    }
                    else
                    {
                        onRampUp++;
                    }
                }

                if (at.CellId == cellarId && local.Z == cellarFloor)
                {
                    onCellarFloor++;
                }
            }
        }

        string path = string.Join(" → ", cells.Select(c => $"0x{c:X8}"));
        cells.Should().Equal([room, cellarId, room], $"down into the cellar and back up into the room: {path}\n{trace}");
        Vector3 end = engine.ToLandblockLocal(TestData.Holtburg, at.Position);
        end.Z.Should().Be(94f, $"back on the room's floor: {at}\n{trace}");
        onRampDown.Should().BeGreaterThanOrEqualTo(cottage ? 25 : 30, $"frames on the recorded ramp going down ({onRampDown}); worst plane error {worstRamp}\n{trace}");
        onRampUp.Should().BeGreaterThanOrEqualTo(cottage ? 25 : 30, $"frames on the recorded ramp going up ({onRampUp}); worst plane error {worstRamp}\n{trace}");
        onCellarFloor.Should().BeGreaterThanOrEqualTo(40, $"frames on the cellar's floor ({onCellarFloor})\n{trace}");
    }

    [Fact]
    public void Each_stair_s_walkable_top_is_the_recorded_ramp_vertex_for_vertex()
    {
        foreach ((uint cellId, GfxObj stair, Stab placement) in ObjectPlacements.CellarStairs())
        {
            Ramp ramp = cellId == ObjectPlacements.CottageCellar ? CottageRamp : BuildingBRamp;
            placement.Id.Should().Be(stair.Id);
            placement.Frame.Origin.Should().Be(Vector3.Zero, "vertices are landblock-local");
            placement.Frame.Orientation.Should().Be(Quaternion.Identity);
            stair.PhysicsPolygons.Values
                .Select(p => p.VertexIds.Select(id => stair.VertexArray.Vertices[(ushort)id].Origin).ToArray())
                .Should().ContainSingle(v => v.SequenceEqual(ramp.Vertices), $"0x{stair.Id:X8}: one polygon is exactly the recorded ramp, in its recorded order");
        }
    }

    [Fact]
    public void Each_stair_is_a_closed_solid_facing_outward()
    {
        // Closed and consistently wound: the polygons' area vectors sum to zero. Facing outward: the
        // volume by the divergence theorem is the profile's area times the width, positive.
        foreach ((_, GfxObj stair, _) in ObjectPlacements.CellarStairs())
        {
            Vector3 origin = stair.VertexArray.Vertices[0].Origin;
            double volume = 0;
            var sum = Vector3.Zero;
            var xs = new List<float>();
            var profile = new SortedDictionary<float, List<float>>();
            float bottom = stair.VertexArray.Vertices.Values.Min(v => v.Origin.Z);
            foreach (Polygon polygon in stair.PhysicsPolygons.Values)
            {
                Vector3[] v = [.. polygon.VertexIds.Select(id => stair.VertexArray.Vertices[(ushort)id].Origin - origin)];
                for (int i = 1; i + 1 < v.Length; i++)
                {
                    Vector3 area = Vector3.Cross(v[i] - v[0], v[i + 1] - v[0]) / 2f;
                    sum += area;
                    volume += Vector3.Dot(v[0], Vector3.Cross(v[i], v[i + 1])) / 6.0;
                }
            }

            foreach (SWVertex vertex in stair.VertexArray.Vertices.Values)
            {
                xs.Add(vertex.Origin.X);
                if (vertex.Origin.Z > bottom)
                {
                    (profile.TryGetValue(vertex.Origin.Y, out List<float>? zs) ? zs : profile[vertex.Origin.Y] = []).Add(vertex.Origin.Z);
                }
            }

            // The profile's area: trapezoids between successive y, from the top at each y (a riser's y has
            // two top heights: the lower one on the side toward the stair's foot) down to the bottom.
            float[] ys = [.. profile.Keys];
            bool rising = profile[ys[^1]].Max() > profile[ys[0]].Max();
            double section = 0;
            for (int i = 0; i + 1 < ys.Length; i++)
            {
                float left = rising ? profile[ys[i]].Max() : profile[ys[i]].Min();
                float right = rising ? profile[ys[i + 1]].Min() : profile[ys[i + 1]].Max();
                section += (ys[i + 1] - ys[i]) * (((left + right) / 2.0) - bottom);
            }

            double expected = section * (xs.Max() - xs.Min());
            sum.Length().Should().BeLessThan(1e-3f, $"0x{stair.Id:X8}: the area vectors sum to {sum}");
            volume.Should().BeApproximately(expected, 1e-3 * expected, $"0x{stair.Id:X8}: volume {volume} m³, profile × width {expected} m³");
        }
    }

    [Fact]
    public void A_mover_risen_above_its_cellar_s_ceiling_on_the_stair_steps_onto_the_room_s_floor_beside_the_opening()
    {
        // The defect this fixed: on the cottage ramp at y 5.9 (z 93.898, above the cellar's ceiling and its
        // opening at 93.8), a step west left the mover in the cellar 0x0147, whose only floor under the end
        // point is the cellar's own, 2.95 m below: it fell back into the cellar instead of stepping up 0.1 m
        // onto the room's floor (94).
        PhysicsEngine engine = Engine("centred");
        var onRamp = new Vector3(141.3f, 5.9f, (float)CottageRamp.PlaneZ(new Vector3(141.3f, 5.9f, 0f)));
        ResolveResult there = engine.Resolve(onRamp, ObjectPlacements.CottageCellar, Vector3.Zero, Step);
        there.Position.Z.Should().BeApproximately(93.8984f, 1e-3f, $"on the ramp: {there}");

        ResolveResult r = engine.Resolve(there.Position, there.CellId, new Vector3(-0.9f, 0f, 0f), Step);

        r.CellId.Should().Be(CottageRoom, $"{r}");
        r.Position.Z.Should().Be(94f, $"{r}");
        r.IsOnGround.Should().BeTrue($"{r}");
    }
}
